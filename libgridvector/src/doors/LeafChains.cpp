// Beyond the paper: leaf chains, a leaf cut by Fig. 4's split made one candidate again.
#include "doors/LeafChains.h"

#include "doors/DoorGeometry.h"

#include <algorithm>
#include <cmath>

namespace gridvector::doors
{
using mrpt::math::TPoint2D;

LeafChains::LeafChains(const std::vector<GridVector>& vectors, const DoorOptions& opts)
	: v_(vectors), n_(vectors.size())
{
	const double maxTurn = radians(kLeafChainMaxTurnDeg);
	for (size_t a = 0; a < n_; ++a)
	{
		if (v_[a].state != VectorState::Dynamic || v_[a].length() >= opts.minDoorLength) continue;
		const Box2D near = endBox(v_[a], kLeafChainGap);  // b's meeting end lies within kLeafChainGap of a's joint
		for (size_t b = 0; b < n_; ++b)
		{
			if (b == a || v_[b].state != VectorState::Static || v_[b].length() > opts.maxDoorLength ||
				!holdsAnEndOf(near, v_[b]))
				continue;
			for (int ea = 0; ea < 2; ++ea)
				for (int eb = 0; eb < 2; ++eb)
				{
					// a's end ea meets b's end eb; the chain runs from a's other end to b's other end
					const TPoint2D from = ea ? v_[a].start() : v_[a].end(), joint = ea ? v_[a].end() : v_[a].start();
					const TPoint2D meet = eb ? v_[b].end() : v_[b].start(), to = eb ? v_[b].start() : v_[b].end();
					if (dist(joint, meet) > kLeafChainGap) continue;
					const double ta = std::atan2(joint.y - from.y, joint.x - from.x);
					const double tb = std::atan2(to.y - meet.y, to.x - meet.x);
					if (std::abs(mrpt::math::wrapToPi(ta - tb)) > maxTurn) continue;
					const double len = dist(from, to);
					if (len < opts.minDoorLength || len > opts.maxDoorLength) continue;
					GridVector chain(from, to, GridOptions{});
					chain.state = VectorState::Dynamic;  // its dynamic piece is the door candidate
					v_.push_back(std::move(chain));
					parts_.emplace_back(a, b);
				}
		}
	}
}

std::vector<size_t> LeafChains::pieces(const std::vector<size_t>& indices) const
{
	std::vector<size_t> out;
	for (size_t k : indices)
	{
		if (k < n_)
			out.push_back(k);
		else
			out.push_back(parts_[k - n_].first), out.push_back(parts_[k - n_].second);
	}
	std::sort(out.begin(), out.end());
	out.erase(std::unique(out.begin(), out.end()), out.end());
	return out;
}

}  // namespace gridvector::doors
