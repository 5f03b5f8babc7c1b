#include "map/CompactMap.h"
#include "map/HalfFloat.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace gridvector
{
namespace
{
/** Layout of the buffer; decode() refuses another. */
constexpr uint8_t kLayout = 1;
/** Most columns a stored vector may claim (GridVector's own bound: a 100 km wall at 1 cm). */
constexpr uint64_t kMaxColumns = 10'000'000;
/** The gravity centre's byte: 128 steps per cell, from half a cell before it. */
constexpr double kCentreSteps = 128.0;
/** Endpoints are stored on a lattice of 2^-10 m (1 mm, far below a cell), as varints of differences. */
constexpr double kEndpointStep = 1.0 / 1024;
/** Timestamps are stored in hundredths of a second from the map's first (a scan lasts 25-200 ms). */
constexpr double kTimeStep = 0.01;
/** Largest coordinate stored [m]: 2^40 steps, beyond any map (a larger one is not a map). */
constexpr double kMaxCoordinate = 1e9;

int64_t quantise(double x)
{
	if (!(std::abs(x) < kMaxCoordinate)) throw std::invalid_argument("CompactMap: coordinate " + std::to_string(x));
	return std::llround(x / kEndpointStep);
}

enum CellKind : uint8_t
{
	kEmpty = 0,
	kPrior = 1,
	kObserved = 2,
	kPoints = 3
};

class Writer
{
   public:
	explicit Writer(std::vector<uint8_t>& b) : b_(b) {}
	void u8(uint8_t v) { b_.push_back(v); }
	void varint(uint64_t v)
	{
		while (v >= 0x80) b_.push_back(uint8_t(v | 0x80)), v >>= 7;
		b_.push_back(uint8_t(v));
	}
	void zigzag(int64_t v) { varint((uint64_t(v) << 1) ^ uint64_t(v >> 63)); }
	void f32(float f) { raw(&f, 4); }
	void f64(double d) { raw(&d, 8); }
	void u16(uint16_t v) { raw(&v, 2); }
	void raw(const void* p, size_t n)
	{
		const auto* c = static_cast<const uint8_t*>(p);
		b_.insert(b_.end(), c, c + n);
	}

   private:
	std::vector<uint8_t>& b_;
};

class Reader
{
   public:
	explicit Reader(const std::vector<uint8_t>& b) : b_(b) {}
	[[noreturn]] static void corrupt(const std::string& what) { throw std::runtime_error("compact map: " + what); }
	void need(size_t n) const
	{
		if (b_.size() - pos_ < n) corrupt("truncated at byte " + std::to_string(pos_));
	}
	uint8_t u8()
	{
		need(1);
		return b_[pos_++];
	}
	uint64_t varint()
	{
		uint64_t v = 0;
		for (int shift = 0; shift < 64; shift += 7)
		{
			const uint8_t c = u8();
			v |= uint64_t(c & 0x7f) << shift;
			if (!(c & 0x80)) return v;
		}
		corrupt("a varint longer than 64 bits");
	}
	int64_t zigzag()
	{
		const uint64_t u = varint();
		return int64_t(u >> 1) ^ -int64_t(u & 1);
	}
	float f32() { return rawAs<float>(); }
	double f64() { return rawAs<double>(); }
	uint16_t u16() { return rawAs<uint16_t>(); }
	size_t left() const { return b_.size() - pos_; }
	const uint8_t* here() const { return b_.data() + pos_; }
	void skip(size_t n)
	{
		need(n);
		pos_ += n;
	}

   private:
	template <class T>
	T rawAs()
	{
		need(sizeof(T));
		T v;
		std::memcpy(&v, b_.data() + pos_, sizeof(T));
		pos_ += sizeof(T);
		return v;
	}
	const std::vector<uint8_t>& b_;
	size_t pos_ = 0;
};

CellKind kindOf(const GridCell& c, double prior)
{
	if (c.n_acc > 0) return kPoints;
	if (c.n_occupy == 0 && c.n_visit == 0) return kEmpty;
	if (std::abs(double(c.n_occupy) - prior * c.n_visit) <= 1e-6 * c.n_visit) return kPrior;
	return kObserved;
}

uint8_t centreByte(double acc, double n, double res)
{
	return uint8_t(std::clamp(std::lround((acc / n / res + 0.5) * kCentreSteps), 0l, 255l));
}

/** Smallest k >= 0 with largest / 2^k below the ceiling. */
int scaleExponent(const GridVector& v)
{
	float largest = 0;
	for (const GridCell& c : v.cells()) largest = std::max({largest, c.n_occupy, c.n_visit, c.n_acc});
	int k = 0;
	while (largest / std::ldexp(1.f, k) >= CompactMap::kHalfCountCeiling && k < 31) ++k;
	if (!(largest / std::ldexp(1.f, k) < CompactMap::kHalfCountCeiling))  // also NaN
		throw std::invalid_argument("CompactMap: a count of " + std::to_string(largest) + " cannot be stored");
	return k;
}
}  // namespace

// Eq. 1-2 per vector, in the bytes described in the header.
CompactMap CompactMap::encode(const std::vector<GridVector>& vectors)
{
	CompactMap m;
	m.count_ = vectors.size();
	Writer w(m.bytes_);
	w.u8(kLayout);
	w.varint(vectors.size());
	const double base = vectors.empty() ? 0 : vectors.front().timestamp;
	w.f64(base);
	w.u8(uint8_t(vectors.empty() ? 1 : vectors.front().rows()));
	uint64_t prevId = 0;
	int64_t prevX = 0, prevY = 0;
	for (const GridVector& v : vectors)
	{
		if (v.rows() != vectors.front().rows())
			throw std::invalid_argument("CompactMap: the vectors of one map must share the grid's width");
		// endpoints on the kEndpointStep lattice: the start from the previous start, the end from the start
		const int64_t sx = quantise(v.start().x), sy = quantise(v.start().y);
		w.zigzag(sx - prevX), w.zigzag(sy - prevY);
		w.zigzag(quantise(v.end().x) - sx), w.zigzag(quantise(v.end().y) - sy);
		prevX = sx, prevY = sy;
		w.varint(uint64_t(v.cols()));
		w.zigzag(v.scanIndex);
		w.zigzag(int64_t(v.id - prevId));
		prevId = v.id;
		w.varint(v.mergedCount);
		w.zigzag(std::llround((v.timestamp - base) / kTimeStep));
		const int k = scaleExponent(v);
		const bool wholePoints = std::all_of(v.cells().begin(), v.cells().end(), [](const GridCell& c) {
			return c.n_acc == std::floor(c.n_acc) && c.n_acc < 4294967296.f;
		});
		w.u8(uint8_t(uint8_t(v.state) | (wholePoints ? 4 : 0) | (k << 3)));
		const float unscale = std::ldexp(1.f, -k);
		const double prior = v.priorRatio(), res = v.resolution();
		const auto& cells = v.cells();
		const size_t codeStart = m.bytes_.size();
		m.bytes_.resize(codeStart + (cells.size() * 2 + 7) / 8, 0);
		for (size_t i = 0; i < cells.size(); ++i)
			m.bytes_[codeStart + i / 4] |= uint8_t(kindOf(cells[i], prior) << (2 * (i % 4)));
		for (const GridCell& c : cells)
			switch (kindOf(c, prior))
			{
				case kEmpty:
					break;
				case kPrior:
					w.u16(toHalf(c.n_visit * unscale));
					break;
				case kObserved:
					w.u16(toHalf(c.n_occupy * unscale)), w.u16(toHalf(c.n_visit * unscale));
					break;
				case kPoints:
					w.u16(toHalf(c.n_occupy * unscale)), w.u16(toHalf(c.n_visit * unscale));
					if (wholePoints)
						w.varint(uint64_t(c.n_acc));
					else
						w.u16(toHalf(c.n_acc * unscale));
					w.u8(centreByte(c.x_acc, c.n_acc, res)), w.u8(centreByte(c.y_acc, c.n_acc, res));
					break;
			}
	}
	m.bytes_.shrink_to_fit();
	return m;
}

CompactMap CompactMap::fromBytes(std::vector<uint8_t> bytes)
{
	CompactMap m;
	m.bytes_ = std::move(bytes);
	m.bytes_.shrink_to_fit();
	Reader r(m.bytes_);
	if (r.u8() != kLayout) Reader::corrupt("unknown layout");
	m.count_ = size_t(r.varint());
	return m;
}

std::vector<GridVector> CompactMap::decode(const GridOptions& grid) const
{
	Reader r(bytes_);
	if (bytes_.empty()) return {};
	if (r.u8() != kLayout) Reader::corrupt("unknown layout");
	const uint64_t n = r.varint();
	const double base = r.f64();
	const int rows = r.u8();
	if (n > 0 && rows != 2 * grid.halfWidth + 1)
		Reader::corrupt("grids of " + std::to_string(rows) + " rows, the config says " +
						std::to_string(2 * grid.halfWidth + 1));
	const double prior = double(float(grid.priorOccupy)) / double(float(grid.priorVisit));
	std::vector<GridVector> out;
	out.reserve(size_t(std::min<uint64_t>(n, r.left() / 20 + 1)));  // a vector takes at least 20 bytes
	uint64_t prevId = 0;
	int64_t prevX = 0, prevY = 0;
	for (uint64_t i = 0; i < n; ++i)
	{
		const std::string rec = "vector " + std::to_string(i) + ": ";
		const int64_t sx = prevX + r.zigzag(), sy = prevY + r.zigzag();
		const int64_t ex = sx + r.zigzag(), ey = sy + r.zigzag();
		prevX = sx, prevY = sy;
		const mrpt::math::TPoint2D s(double(sx) * kEndpointStep, double(sy) * kEndpointStep);
		const mrpt::math::TPoint2D e(double(ex) * kEndpointStep, double(ey) * kEndpointStep);
		const uint64_t cols = r.varint();
		if (cols < 1 || cols > kMaxColumns) Reader::corrupt(rec + std::to_string(cols) + " columns");
		const int64_t scanIndex = r.zigzag();
		const uint64_t id = prevId + uint64_t(r.zigzag());
		prevId = id;
		const uint64_t merged = r.varint();
		const double t = base + double(r.zigzag()) * kTimeStep;
		const uint8_t flags = r.u8();
		const uint8_t state = flags & 3;
		const bool wholePoints = flags & 4;
		const int k = flags >> 3;
		if (state > 2) Reader::corrupt(rec + "state " + std::to_string(state));
		const float scale = std::ldexp(1.f, k);
		const size_t ncells = size_t(rows) * size_t(cols);
		const size_t codeBytes = (ncells * 2 + 7) / 8;
		r.need(codeBytes);
		const std::vector<uint8_t> codes(r.here(), r.here() + codeBytes);
		r.skip(codeBytes);
		std::vector<GridCell> cells(ncells, GridCell{0.f, 0.f, 0.f, 0.f, 0.f});
		const double res = grid.resolution;
		for (size_t c = 0; c < ncells; ++c)
		{
			GridCell& g = cells[c];
			switch ((codes[c / 4] >> (2 * (c % 4))) & 3)
			{
				case kEmpty:
					break;
				case kPrior:
					g.n_visit = fromHalf(r.u16()) * scale;
					g.n_occupy = float(prior * g.n_visit);
					break;
				case kObserved:
					g.n_occupy = fromHalf(r.u16()) * scale;
					g.n_visit = fromHalf(r.u16()) * scale;
					break;
				case kPoints:
				{
					g.n_occupy = fromHalf(r.u16()) * scale;
					g.n_visit = fromHalf(r.u16()) * scale;
					g.n_acc = wholePoints ? float(r.varint()) : fromHalf(r.u16()) * scale;
					const double mx = (r.u8() / kCentreSteps - 0.5) * res, my = (r.u8() / kCentreSteps - 0.5) * res;
					g.x_acc = float(g.n_acc * mx);
					g.y_acc = float(g.n_acc * my);
					break;
				}
			}
			if (!(g.n_occupy >= 0 && g.n_visit >= 0 && g.n_acc >= 0 && std::isfinite(g.n_occupy) &&
				  std::isfinite(g.n_visit) && std::isfinite(g.n_acc)))
				Reader::corrupt(rec + "a cell with a negative or non-finite count");
		}
		GridVector v;
		try
		{
			v = GridVector::fromParts(s, e, grid, int(cols), std::move(cells));
		}
		catch (const std::invalid_argument& ex)
		{
			Reader::corrupt(rec + ex.what());
		}
		v.scanIndex = scanIndex;
		v.timestamp = t;
		v.id = id;
		v.state = VectorState(state);
		v.mergedCount = uint32_t(std::min<uint64_t>(merged, UINT32_MAX));
		out.push_back(std::move(v));
	}
	if (r.left() != 0) Reader::corrupt(std::to_string(r.left()) + " bytes after the last vector");
	return out;
}

}  // namespace gridvector
