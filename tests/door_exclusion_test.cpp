// DoorExclusion (Sec. 5.3): doors detected on each E-step's map, their states kept out of the
// M-step's static children, accumulated over the iterations, Eq. 25's changed children.
#include "doors/DoorExclusion.h"
#include "em/EmSlam.h"
#include "extraction/VectorExtractor.h"
#include <gridvector/io/LogReader.h>
#include "sim/Simulator.h"
#include "sim/TruthFiles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include <unistd.h>

using namespace gridvector;
using mrpt::math::TPoint2D;
using mrpt::math::TPose2D;

namespace
{
constexpr auto S = VectorState::Static;
constexpr auto D = VectorState::Dynamic;

// A child of scan `scan` (global frame), every column seen `occupancy` of 20 times (Eq. 6).
GridVector child(double x1, double y1, double x2, double y2, VectorState s, int64_t scan, uint64_t parent)
{
	GridVector v(TPoint2D(x1, y1), TPoint2D(x2, y2), GridOptions{});
	const float occ = s == S ? 20.f : 4.f;
	for (int r = 0; r < v.rows(); ++r)
		for (int c = 0; c < v.cols(); ++c)
		{
			GridCell& cell = v.cell(r, c);
			cell.n_visit = 20;
			cell.n_occupy = r == v.halfWidth() ? occ : 0.f;
		}
	v.state = s;
	v.scanIndex = scan;
	v.id = EStep::childId(parent, 0);
	return v;
}

// Fig. 10's door: walls ending at the frame x = 3 and x = 4, a 0.9 m leaf hinged at (3, 0), seen
// open (90 deg, dynamic: later scans saw through) and half open (45 deg, static: Eq. 6 saw that
// state long); a wall far away.
std::vector<GridVector> doorWorld()
{
	return {child(0, 0, 3, 0, S, 0, 1), child(4, 0, 6, 0, S, 0, 2), child(3.02, 0.03, 3.02, 0.92, D, 1, 3),  // open
			child(3.01, 0.0, 3.64, 0.64, S, 2, 4),  // half open, kept static by Eq. 6
			child(6, 5, 0, 5, S, 2, 5)};
}

bool has(const std::vector<GridVector>& vs, uint64_t id)
{
	return std::any_of(vs.begin(), vs.end(), [&](const GridVector& v) { return v.id == id; });
}
std::vector<uint64_t> flat(const std::vector<std::vector<uint64_t>>& ids)
{
	std::vector<uint64_t> out;
	for (const auto& s : ids) out.insert(out.end(), s.begin(), s.end());
	std::sort(out.begin(), out.end());
	return out;
}
}  // namespace

TEST(DoorExclusion, ALeafKeptStaticByEq6IsKeptOutOfTheMStep)
{
	GridVectorConfig cfg;
	const EStep estep(cfg.estep, cfg.grid);
	DoorExclusion ex(cfg, estep);
	const auto children = doorWorld();
	std::vector<std::vector<uint64_t>> changed(3);
	DoorExclusionFigures fig;
	const auto kept = ex.apply(children, changed, fig);
	ASSERT_EQ(fig.found, 1u);
	ASSERT_EQ(ex.doors().size(), 1u);
	EXPECT_NEAR(ex.doors()[0].hinge.x, 3.0, 0.05);
	EXPECT_NEAR(ex.doors()[0].hinge.y, 0.0, 0.05);
	// the static leaf is out; the walls and the far wall are registered whole; the dynamic leaf is
	// passed on as it is (the M-step registers static children only)
	EXPECT_FALSE(has(kept, children[3].id));
	for (size_t k : {0, 1, 4}) EXPECT_TRUE(has(kept, children[k].id)) << k;
	EXPECT_EQ(fig.excluded, 1u);
	EXPECT_EQ(fig.cut, 0u);
	const auto segs = EmSlam::staticSegments(kept, {TPose2D(0, 0, 0), TPose2D(0, 0, 0), TPose2D(0, 0, 0)});
	EXPECT_EQ(segs[0].size(), 2u);
	EXPECT_EQ(segs[1].size(), 0u);
	EXPECT_EQ(segs[2].size(), 1u);  // the far wall only
	// Eq. 25: the leaf's edges see a changed child
	EXPECT_EQ(flat(changed), std::vector<uint64_t>{children[3].id});

	// the same map again: nothing changed
	std::vector<std::vector<uint64_t>> again(3);
	ex.apply(children, again, fig);
	EXPECT_TRUE(flat(again).empty());
}

TEST(DoorExclusion, DoorsAccumulateAndCutAWallAlongAState)
{
	GridVectorConfig cfg;
	const EStep estep(cfg.estep, cfg.grid);
	DoorExclusion ex(cfg, estep);
	std::vector<std::vector<uint64_t>> changed(4);
	DoorExclusionFigures fig;
	ex.apply(doorWorld(), changed, fig);
	ASSERT_EQ(ex.doors().size(), 1u);
	// a later map without the dynamic state: no door found on it, the one found before stays
	// ("detected gradually"); a static vector from the hinge along the open state and on for 1.1 m
	// beyond its tip is cut there: the 0.9 m of the state out, the rest kept, the first piece
	// keeping the child's id
	auto later = doorWorld();
	later.erase(later.begin() + 2);
	later.push_back(child(3.0, 0.0, 3.0, 2.0, S, 3, 6));
	changed.assign(4, {});
	const auto kept = ex.apply(later, changed, fig);
	EXPECT_EQ(fig.found, 0u);
	EXPECT_EQ(fig.doors, 1u);
	EXPECT_FALSE(has(kept, later[2].id));  // the static half-open leaf: still out
	EXPECT_EQ(fig.excluded, 1u);
	EXPECT_EQ(fig.cut, 1u);
	const auto piece =
		std::find_if(kept.begin(), kept.end(), [&](const GridVector& v) { return v.id == later.back().id; });
	ASSERT_NE(piece, kept.end());
	EXPECT_NEAR(piece->start().y, 0.9, 0.11);
	EXPECT_NEAR(piece->end().y, 2.0, 1e-9);
	// Eq. 25: only the newly cut child changed (the leaf was out before too)
	EXPECT_EQ(flat(changed), std::vector<uint64_t>{later.back().id});
}

TEST(DoorExclusion, PieceIdsKeepTheChildInTheLowBits)
{
	const uint64_t c = EStep::childId(12345, 3);
	EXPECT_EQ(DoorExclusion::pieceId(c, 1) & ((uint64_t(1) << 56) - 1), c);
	EXPECT_NE(DoorExclusion::pieceId(c, 1), DoorExclusion::pieceId(c, 2));
	EXPECT_THROW(DoorExclusion::pieceId(c, 0), std::overflow_error);
	EXPECT_THROW(DoorExclusion::pieceId(c, 256), std::overflow_error);
	EXPECT_THROW(DoorExclusion::pieceId(uint64_t(1) << 60, 1), std::overflow_error);
}

namespace
{
// gv-sim's long corridor (swinging doors, people), 400 scans, as gv-em-slam reads and extracts it.
void simulatedCorridor(std::vector<LocalScan>& scans, std::vector<TPose2D>& odo, const GridVectorConfig& cfg)
{
	sim::SimOptions o;
	o.world = "long-corridor";
	o.seed = 2;
	o.scans = 400;
	const auto dir = std::filesystem::temp_directory_path() / ("door_exclusion_test_" + std::to_string(::getpid()));
	sim::writeSimulation(sim::simulate(o), dir.string());
	io::ReadOptions ro;
	ro.quiet = true;
	const io::LogData log = io::readLog((dir / "sim.log").string(), ro);
	std::filesystem::remove_all(dir);
	const VectorExtractor ex(cfg.extraction, cfg.grid);
	for (size_t t = 0; t < log.scans.size(); ++t)
	{
		scans.push_back(ex.extract(*log.scans[t].scan));
		scans.back().scanIndex = int64_t(t);
		scans.back().timestamp = log.scans[t].timestamp;
		odo.push_back(log.scans[t].odometry);
	}
}

// Per EM iteration, the static segments the M-step registered.
std::vector<size_t> registered(const GridVectorConfig& cfg, const std::vector<LocalScan>& scans,
							   const std::vector<TPose2D>& odo, EmResult& res)
{
	std::vector<size_t> out;
	EmSlam em(cfg);
	em.setMStepObserver(
		[&](int, const MStep&, const std::vector<std::vector<MatchSegment>>& statics, const std::vector<size_t>&) {
			size_t n = 0;
			for (const auto& s : statics) n += s.size();
			out.push_back(n);
		});
	res = em.run(scans, odo);
	return out;
}
}  // namespace

// Sec. 5.3: with doors.during_em the M-step after the first E-step registers the static children
// less the door states found on that E-step's map; without it, every static child.
TEST(DoorExclusion, TheMStepNoLongerRegistersDoorStates)
{
	GridVectorConfig cfg;
	std::vector<LocalScan> scans;
	std::vector<TPose2D> odo;
	simulatedCorridor(scans, odo, cfg);
	EmResult off, on;
	const auto nOff = registered(cfg, scans, odo, off);
	cfg.doors.duringEm = true;
	const auto nOn = registered(cfg, scans, odo, on);
	ASSERT_GE(nOff.size(), 2u);
	ASSERT_GE(nOn.size(), 2u);
	EXPECT_EQ(nOff[0], nOn[0]);  // M-step 1: every vector, before any E-step
	const EmIteration& first = on.iterations[0];
	EXPECT_EQ(nOff[1], off.iterations[0].staticVectors);
	EXPECT_EQ(off.iterations[0].doors.doors, 0u);  // the key off: nothing detected during EM
	ASSERT_GT(first.doors.found, 0u);
	EXPECT_EQ(first.doors.doors, first.doors.found);
	EXPECT_GT(first.doors.excluded, 0u);
	// M-step 2 registers the static children of E-step 1 but the door leaves (out whole) and with
	// each wall cut at a door state as one or more pieces
	EXPECT_LE(nOn[1], first.staticVectors - first.doors.excluded + first.doors.cut);
	EXPECT_GE(nOn[1], first.staticVectors - first.doors.excluded - first.doors.cut);
	EXPECT_LT(nOn[1], first.staticVectors);
	EXPECT_TRUE(on.converged);
	for (const auto& it : on.iterations) EXPECT_GE(it.doors.doors, first.doors.doors);  // accumulated
}
