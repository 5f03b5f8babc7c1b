// SequentialChain (Sec. 4.2): each scan registered against its predecessors, chained into the first estimate.
#include "em_world.h"

#include "estep/EStep.h"
#include "mstep/SequentialChain.h"

#include <gtest/gtest.h>

using namespace gridvector;
using emtest::TPose2D;

namespace
{
struct Ring
{
	Poses truth = emtest::ringPath(1, 0.5), odo = emtest::odometryOf(truth, 7);
	Scans scans;
	GridVectorConfig cfg;
	ConstraintSet book{cfg.matcher};
	PairRegistration reg{cfg, book};
	ProgressFn progress;
	Ring()
	{
		const auto walls = emtest::corridorWorld();
		uint64_t id = 1;
		for (size_t t = 0; t < truth.size(); ++t)
		{
			scans.push_back(MatchSegment::fromVectors(emtest::observe(walls, truth[t], 6.0, unsigned(t)).vectors));
			for (auto& s : scans.back()) s.id = EStep::childId(id++, 0);
		}
		book.beginStep(scans, nullptr);
	}
};
}  // namespace

TEST(SequentialChain, TheChainRemovesTheOdometrysDrift)
{
	Ring r;
	const SequentialChain chain(r.cfg, r.book, r.reg, r.odo, r.progress);
	Poses poses;
	MStepReport rep;
	chain.chain(r.scans, poses, rep);
	ASSERT_EQ(poses.size(), r.truth.size());
	EXPECT_GT(emtest::ate(r.odo, r.truth), 0.3);
	EXPECT_LT(emtest::ate(poses, r.truth), 0.5 * emtest::ate(r.odo, r.truth));
	EXPECT_EQ(rep.added, r.book.edges.size());
	for (uint32_t i = 1; i < r.scans.size(); ++i)  // every scan registered against a predecessor in the window
		EXPECT_TRUE(r.book.hasEdgeNear(
			i, i > uint32_t(r.cfg.mstep.sequentialWindow) ? i - r.cfg.mstep.sequentialWindow : 0, i - 1))
			<< i;
	for (const auto& [key, c] : r.book.edges)
	{
		EXPECT_EQ(c.kind, EdgeKind::Sequential);
		EXPECT_LE(key.second - key.first, uint32_t(r.cfg.mstep.sequentialWindow));
	}
}

// Later M-steps: a missing pair is registered again when something changed, not when nothing did.
TEST(SequentialChain, AMissingPairIsRetriedWhereSomethingChanged)
{
	Ring r;
	const SequentialChain chain(r.cfg, r.book, r.reg, r.odo, r.progress);
	Poses poses;
	MStepReport first;
	chain.chain(r.scans, poses, first);
	const Constraint gone = r.book.edges.at({10, 11});
	r.book.edges.erase({10, 11});
	r.book.fail({10, 11}, poses[11] - poses[10]);
	MStepReport rep;
	chain.addMissing(r.scans, poses, rep);
	EXPECT_EQ(rep.registrations, 0u);  // failed and nothing changed since
	r.scans[11].pop_back();  // the E-step changed scan 11's static vectors
	r.book.beginStep(r.scans, nullptr);
	chain.addMissing(r.scans, poses, rep);
	EXPECT_GE(rep.registrations, 1u);
	ASSERT_EQ(r.book.edges.count({10, 11}), 1u);
	EXPECT_LT(std::hypot(r.book.edges.at({10, 11}).z.x - gone.z.x, r.book.edges.at({10, 11}).z.y - gone.z.y), 0.05);
}
