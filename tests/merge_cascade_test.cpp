// Algorithm 2 cascaded: merged with the correspondents, then the merged vector with its own; refusals remembered.
#include "map/Correspondence.h"
#include "map/MergeCascade.h"

#include <gtest/gtest.h>

#include "wall_pieces.h"

#include <cmath>

using namespace gridvector;
using gvtest::arcPiece;
using gvtest::wallPiece;

namespace
{
/** A pool over a list of vectors, keyed by position; `all` offers every vector left,
 * otherwise the Sec. 3.2 criteria decide. Records what it was asked. */
struct ListPool
{
	std::vector<GridVector> vectors;
	std::vector<bool> left;
	bool all = false;
	size_t calls = 0;
	std::vector<std::vector<uint64_t>> absorbed;

	explicit ListPool(std::vector<GridVector> v) : vectors(std::move(v)), left(vectors.size(), true) {}
	MergePool pool()
	{
		return {[this](const GridVector& v) {
					++calls;
					std::vector<MergeCandidate> out;
					for (size_t k = 0; k < vectors.size(); ++k)
						if (left[k] && (all || corresponds(v, vectors[k], MapOptions{})))
							out.push_back({k, &vectors[k]});
					return out;
				},
				[this](const std::vector<MergeCandidate>& taken) {
					absorbed.emplace_back();
					for (const MergeCandidate& c : taken) left[c.key] = false, absorbed.back().push_back(c.key);
				}};
	}
};
}  // namespace

TEST(MergeCascade, GoesOnWithTheMergedVector)
{
	// a and b: one wall, not overlapping. c overlaps both but lies 0.1 m off: it
	// corresponds to a only; the merge of a and c, dominated by a's points, matches b.
	ListPool p({wallPiece({0, 0}, {4, 0}), wallPiece({5, -0.06}, {8, -0.06})});
	GridVector v = wallPiece({3, 0.1}, {5.5, 0.1}, 0.08);
	ASSERT_FALSE(corresponds(v, p.vectors[1], MapOptions{}));
	const MergeCascadeStats st = mergeCascade(VectorMerger(), v, p.pool());
	EXPECT_EQ(st.merges, 2u);
	EXPECT_EQ(st.absorbed, 2u);
	EXPECT_EQ(st.refused, 0u);
	ASSERT_EQ(p.absorbed.size(), 2u);
	EXPECT_EQ(p.absorbed[0], std::vector<uint64_t>{0});
	EXPECT_EQ(p.absorbed[1], std::vector<uint64_t>{1});
	EXPECT_EQ(p.calls, 3u);  // the third finds nothing left
	EXPECT_EQ(v.mergedCount, 3u);
	EXPECT_NEAR(v.start().x, 0, 0.05);
	EXPECT_NEAR(v.end().x, 8, 0.05);
}

TEST(MergeCascade, ARefusedCorrespondentIsNotOfferedAgain)
{
	// pieces of an arc with 0.5 m sagitta over 12 m: the base holds its wall with
	// its neighbour but not with the far piece (VectorMerger's guard)
	ListPool p({arcPiece(36, 3, 9), arcPiece(36, -4, -1)});
	p.all = true;
	GridVector v = arcPiece(36, -1, 3);
	const MergeCascadeStats st = mergeCascade(VectorMerger(), v, p.pool());
	EXPECT_EQ(st.merges, 1u);
	EXPECT_EQ(st.absorbed, 1u);
	EXPECT_EQ(st.refused, 1u);  // once: the second round finds only the refused piece and stops
	ASSERT_EQ(p.absorbed.size(), 1u);
	EXPECT_EQ(p.absorbed[0], std::vector<uint64_t>{1});
	EXPECT_EQ(p.calls, 2u);
	EXPECT_TRUE(p.left[0]);
	EXPECT_NEAR(v.start().x, -4, 0.05);
	EXPECT_NEAR(v.end().x, 3, 0.05);
}

TEST(MergeCascade, NothingCorrespondingLeavesTheVectorAsItWas)
{
	ListPool p({wallPiece({0, 5}, {4, 5})});
	GridVector v = wallPiece({0, 0}, {4, 0});
	v.id = 17;
	const MergeCascadeStats st = mergeCascade(VectorMerger(), v, p.pool());
	EXPECT_EQ(st.merges + st.absorbed + st.refused, 0u);
	EXPECT_EQ(v.id, 17u);
	EXPECT_EQ(v.mergedCount, 1u);
	EXPECT_TRUE(p.absorbed.empty());
}

// a pool that offers one new overlapping piece of the same wall at each round; the
// cascade stops after maxMerges (kMergeCascadeRounds) merges
namespace
{
size_t cascadeOverChain(int rounds, double& endX)
{
	std::vector<GridVector> chain;
	for (int k = 0; k < rounds + 4; ++k) chain.push_back(wallPiece({1.0 + k, 0}, {3.0 + k, 0}));
	ListPool p(chain);
	size_t next = 0;
	MergePool pool = p.pool();
	pool.correspondents = [&](const GridVector&) {
		return next < p.vectors.size() ? std::vector<MergeCandidate>{{next, &p.vectors[next]}}
									   : std::vector<MergeCandidate>{};
	};
	auto absorb = pool.absorb;
	pool.absorb = [&](const std::vector<MergeCandidate>& taken) { absorb(taken), ++next; };
	GridVector v = wallPiece({0, 0}, {2, 0});
	const MergeCascadeStats st = mergeCascade(VectorMerger(), v, pool, rounds);
	endX = v.end().x;
	return st.merges;
}
}  // namespace

TEST(MergeCascade, StopsAfterTheRoundBound)
{
	const int defaultRounds = kMergeCascadeRounds;
	EXPECT_EQ(defaultRounds, 8);  // the value when it was a key
	for (int rounds : {1, 3, defaultRounds})
	{
		double endX = 0;
		EXPECT_EQ(cascadeOverChain(rounds, endX), size_t(rounds)) << rounds;
		EXPECT_NEAR(endX, 2.0 + rounds, 0.05) << rounds;
	}
}
