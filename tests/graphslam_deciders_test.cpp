// Grid-vector registration deciders for MRPT's graphslam-engine: options, registry, behaviour.
#include "graphslam/CGridVectorERD.h"
#include "graphslam/CGridVectorNRD.h"
#include <gridvector/graphslam/DeciderRegistry.h>
#include "posegraph/PoseGraph.h"
#include "graphslam/PoseFusion.h"
#include "graphslam/RunRecorder.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/graphslam/levmarq.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/poses/CPose2D.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "graphslam_ini_files.h"
#include "test_scans.h"

using namespace gridvector::graphslam;
using mrpt::math::TPose2D;
using mrpt::poses::CPose2D;

namespace
{
mrpt::config::CConfigFileMemory ini(const std::string& text) { return mrpt::config::CConfigFileMemory(text); }

// A room with some clutter: enough wall directions for vector matching.
std::vector<gvtest::Seg> world()
{
	auto w = gvtest::room(-6, -4, 6, 4);
	w.push_back({-2, -4, -2, -1.5});
	w.push_back({2, 4, 2, 1.0});
	w.push_back({3.5, -2, 5, -2});
	w.push_back({-5, 2, -3.5, 2});
	return w;
}

mrpt::obs::CObservation::Ptr scanAt(const TPose2D& truth)
{
	auto s = mrpt::obs::CObservation2DRangeScan::Create(gvtest::castScan(truth, world(), {}, 361, M_PI, 20));
	return s;
}

mrpt::obs::CObservation::Ptr odometryAt(const TPose2D& odo)
{
	auto o = mrpt::obs::CObservationOdometry::Create();
	o->odometry = CPose2D(odo);
	return o;
}

/** Ground truth: a straight drive then a turn; odometry with a yaw bias. */
struct Drive
{
	std::vector<TPose2D> truth, odometry;
	Drive()
	{
		TPose2D t(-4, 0, 0), o = t;
		for (int i = 0; i < 40; ++i)
		{
			const TPose2D step = i < 25 ? TPose2D(0.2, 0, 0) : TPose2D(0.1, 0, 0.08);
			t = (CPose2D(t) + CPose2D(step)).asTPose();
			o = (CPose2D(o) + CPose2D(step.x * 1.05, 0, step.phi + 0.01)).asTPose();
			truth.push_back(t);
			odometry.push_back(o);
		}
	}
};

double positionError(const CPose2D& estimateRelToFirst, const TPose2D& truth, const TPose2D& truth0)
{
	const CPose2D rel = CPose2D(truth) - CPose2D(truth0);
	return estimateRelToFirst.distanceTo(rel);
}
}  // namespace

TEST(graphslam_options, defaults_match_the_documented_values)
{
	NodeDeciderOptions n;
	EXPECT_DOUBLE_EQ(n.registrationMaxDistance, 0.5);
	EXPECT_DOUBLE_EQ(n.registrationMaxAngleDeg, 10.0);
	EXPECT_TRUE(n.useOdometry);
	EdgeDeciderOptions e;
	EXPECT_EQ(e.lcMinNodeIdDiff, 30);
	EXPECT_DOUBLE_EQ(e.maxDistance, 3.0);
	EXPECT_EQ(e.sequentialWindow, 3);
	EXPECT_DOUBLE_EQ(e.searchOffset, 0.75);
}

TEST(graphslam_options, reads_shared_and_own_sections)
{
	NodeDeciderOptions n;
	n.load(ini("[NodeRegistrationDeciderParameters]\nregistration_max_distance = 0.2 // m\n"
			   "registration_max_angle = 30\nclass_verbosity = 0\n"
			   "[GridVectorNRD]\nmax_correction_distance = 0.8\nuse_odometry = false\n"),
		   "t.ini");
	EXPECT_DOUBLE_EQ(n.registrationMaxDistance, 0.2);
	EXPECT_DOUBLE_EQ(n.registrationMaxAngleDeg, 30);
	EXPECT_EQ(n.classVerbosity, 0);
	EXPECT_DOUBLE_EQ(n.maxCorrectionDistance, 0.8);
	EXPECT_FALSE(n.useOdometry);
	EdgeDeciderOptions e;
	e.load(ini("[GeneralConfiguration]\nLC_min_nodeid_diff = 12\n"
			   "[GridVectorERD]\nmax_distance = 4.5\nsequential_window = 5\npass_gap = 7\n"
			   "search_offset = 0\n"),
		   "t.ini");
	EXPECT_EQ(e.lcMinNodeIdDiff, 12);
	EXPECT_DOUBLE_EQ(e.maxDistance, 4.5);
	EXPECT_EQ(e.sequentialWindow, 5);
	EXPECT_EQ(e.passGap, 7);
	EXPECT_DOUBLE_EQ(e.searchOffset, 0);
}

TEST(graphslam_options, shared_sections_tolerate_other_deciders_keys)
{
	EdgeDeciderOptions e;
	EXPECT_NO_THROW(e.load(ini("[EdgeRegistrationDeciderParameters]\nICP_goodness_thresh = 0.7\n"
							   "ICP_max_distance = 2\nclass_verbosity = 2\n"),
						   "t.ini"));
	EXPECT_EQ(e.classVerbosity, 2);
}

// MRPT 2.5's edge deciders (CICPCriteriaERD, CLoopCloserERD) and CLevMarqGSO read LC_min_nodeid_diff
// from [GeneralConfiguration] only; CGridVectorERD reads it there too, so swapping the edge decider
// does not change which edges are loop closures. A different value in the deciders' section (MRPT's
// odometry_2DRangeScans.ini has 30 there, 50 in [GeneralConfiguration]) is reported, not used.
TEST(graphslam_options, lc_min_nodeid_diff_is_read_where_mrpts_deciders_read_it)
{
	EdgeDeciderOptions e;
	e.load(ini("[GeneralConfiguration]\nLC_min_nodeid_diff = 50\n"
			   "[EdgeRegistrationDeciderParameters]\nLC_min_nodeid_diff = 30\n"),
		   "t.ini");
	EXPECT_EQ(e.lcMinNodeIdDiff, 50);
	EXPECT_EQ(e.ignoredKeyNote,
			  "t.ini: [EdgeRegistrationDeciderParameters] LC_min_nodeid_diff = 30 is not used: MRPT's edge deciders, "
			  "CLevMarqGSO and CGridVectorERD read it from [GeneralConfiguration] (50)");
	EdgeDeciderOptions alone;  // only in the deciders' section: MRPT's default 30 holds
	alone.load(ini("[EdgeRegistrationDeciderParameters]\nLC_min_nodeid_diff = 12\n"), "t.ini");
	EXPECT_EQ(alone.lcMinNodeIdDiff, 30);
	EXPECT_NE(alone.ignoredKeyNote.find("= 12 is not used"), std::string::npos) << alone.ignoredKeyNote;
	EdgeDeciderOptions same;  // the same value in both: nothing to report
	same.load(ini("[GeneralConfiguration]\nLC_min_nodeid_diff = 20\n"
				  "[EdgeRegistrationDeciderParameters]\nLC_min_nodeid_diff = 20\n"),
			  "t.ini");
	EXPECT_EQ(same.lcMinNodeIdDiff, 20);
	EXPECT_EQ(same.ignoredKeyNote, "");
}

TEST(graphslam_options, unknown_own_key_names_file_section_and_key)
{
	EdgeDeciderOptions e;
	try
	{
		e.load(ini("[GridVectorERD]\nmax_distanse = 4\n"), "my.ini");
		FAIL() << "no exception";
	}
	catch (const std::runtime_error& ex)
	{
		EXPECT_STREQ(ex.what(), "my.ini: unknown key 'max_distanse' in section [GridVectorERD]");
	}
	NodeDeciderOptions n;
	EXPECT_THROW(n.load(ini("[GridVectorNRD]\nregistration_max_distance = 1\n"), "my.ini"), std::runtime_error);
}

TEST(graphslam_options, out_of_range_values_are_rejected)
{
	NodeDeciderOptions n;
	EXPECT_THROW(n.load(ini("[NodeRegistrationDeciderParameters]\nregistration_max_distance = -1\n"), "a.ini"),
				 std::runtime_error);
	EdgeDeciderOptions e;
	EXPECT_THROW(e.load(ini("[GridVectorERD]\nmin_matched_share = 1.5\n"), "a.ini"), std::runtime_error);
	EXPECT_THROW(e.load(ini("[GridVectorERD]\npass_gap = 0\n"), "a.ini"), std::runtime_error);
}

namespace
{
/** The message load() throws for `text`, "" if none. */
template <class Opts>
std::string loadError(const std::string& text)
{
	try
	{
		Opts().load(ini(text), "a.ini");
	}
	catch (const std::runtime_error& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

TEST(graphslam_options, out_of_range_values_are_errors_naming_file_section_key_value_and_why)
{
	const std::vector<std::pair<std::string, std::string>> nodeBad = {
		{"[NodeRegistrationDeciderParameters]\nregistration_max_distance = -1\n",
		 "a.ini: [NodeRegistrationDeciderParameters] registration_max_distance = '-1' must be > 0"},
		{"[NodeRegistrationDeciderParameters]\nclass_verbosity = 7\n",
		 "a.ini: [NodeRegistrationDeciderParameters] class_verbosity = '7' must be in 0..3"},
		{"[GridVectorNRD]\nmax_correction_angle_deg = 400\n",
		 "a.ini: [GridVectorNRD] max_correction_angle_deg = '400' must be in (0, 180]"}};
	for (const auto& [text, expected] : nodeBad) EXPECT_EQ(loadError<NodeDeciderOptions>(text), expected);
	const std::vector<std::pair<std::string, std::string>> edgeBad = {
		{"[GeneralConfiguration]\nLC_min_nodeid_diff = 0\n",
		 "a.ini: [GeneralConfiguration] LC_min_nodeid_diff = '0' must be >= 1"},
		{"[GridVectorERD]\nmin_matched_share = 1.5\n",
		 "a.ini: [GridVectorERD] min_matched_share = '1.5' must be in (0, 1]"},
		{"[GridVectorERD]\npass_gap = 0\n", "a.ini: [GridVectorERD] pass_gap = '0' must be >= 1"},
		{"[GridVectorERD]\nsequential_window = -2\n", "a.ini: [GridVectorERD] sequential_window = '-2' must be >= 0"},
		{"[GridVectorERD]\nsearch_angle_deg = 90\n",
		 "a.ini: [GridVectorERD] search_angle_deg = '90' must be in [0, 90)"}};
	for (const auto& [text, expected] : edgeBad) EXPECT_EQ(loadError<EdgeDeciderOptions>(text), expected);
}

TEST(graphslam_options, values_are_read_whole_not_by_their_first_digits)
{
	// MRPT's read_double / read_int / read_bool made these 0, 1 and false without a word
	EXPECT_EQ(loadError<EdgeDeciderOptions>("[GridVectorERD]\nmin_matched_share = 0.o5\n"),
			  "a.ini: [GridVectorERD] min_matched_share = '0.o5' is not a finite number");
	EXPECT_EQ(loadError<EdgeDeciderOptions>("[GridVectorERD]\npass_gap = 1.5\n"),
			  "a.ini: [GridVectorERD] pass_gap = '1.5' is not an integer");
	EXPECT_EQ(loadError<NodeDeciderOptions>("[GridVectorNRD]\nuse_odometry = ture\n"),
			  "a.ini: [GridVectorNRD] use_odometry = 'ture' is not true or false");
	EXPECT_EQ(loadError<NodeDeciderOptions>("[NodeRegistrationDeciderParameters]\nregistration_max_angle = nan\n"),
			  "a.ini: [NodeRegistrationDeciderParameters] registration_max_angle = 'nan' is not a finite number");
	EXPECT_EQ(loadError<EdgeDeciderOptions>("[EdgeRegistrationDeciderParameters]\nLC_min_nodeid_diff = 3O\n"),
			  "a.ini: [EdgeRegistrationDeciderParameters] LC_min_nodeid_diff = '3O' is not an integer");
	// other deciders' keys in the shared sections stay theirs to read
	EXPECT_EQ(loadError<EdgeDeciderOptions>("[EdgeRegistrationDeciderParameters]\nICP_goodness_thresh = 0.o5\n"), "");
}

TEST(graphslam_options, values_end_as_in_mrpts_graphslam_files)
{
	EdgeDeciderOptions e;
	e.load(ini("[GeneralConfiguration]\nLC_min_nodeid_diff = 12;\n[EdgeRegistrationDeciderParameters]\nclass_verbosity "
			   "= 0 // debug\n"
			   "[GridVectorERD]\nmax_distance = 4.5;\nsearch_offset = 0.25 ; m\nmatch_previous_node = true # x\n"
			   "pass_gap = 7; once a pass\n"),
		   "t.ini");
	EXPECT_EQ(e.lcMinNodeIdDiff, 12);
	EXPECT_EQ(e.classVerbosity, 0);
	EXPECT_DOUBLE_EQ(e.maxDistance, 4.5);
	EXPECT_DOUBLE_EQ(e.searchOffset, 0.25);
	EXPECT_TRUE(e.matchPreviousNode);
	EXPECT_EQ(e.passGap, 7);
}

TEST(graphslam_options, every_graphslam_ini_mrpt_and_we_ship_loads_with_mrpts_values)
{
	const auto files = gvtest::graphslamIniFiles();
	ASSERT_GE(files.size(), 2u) << "MRPT's graphslam-engine .ini files not found in " << gvtest::mrptGraphslamIniDir;
	for (const auto& path : files)
	{
		const mrpt::config::CConfigFile c(path);
		NodeDeciderOptions n, nDefault;
		EdgeDeciderOptions e, eDefault;
		ASSERT_NO_THROW(n.load(c, path)) << path;
		ASSERT_NO_THROW(e.load(c, path)) << path;
		const char* ns = NodeDeciderOptions::sharedSection;
		const char* es = EdgeDeciderOptions::sharedSection;
		EXPECT_EQ(n.registrationMaxDistance,
				  c.read_double(ns, "registration_max_distance", nDefault.registrationMaxDistance))
			<< path;
		EXPECT_EQ(n.registrationMaxAngleDeg,
				  c.read_double(ns, "registration_max_angle", nDefault.registrationMaxAngleDeg))
			<< path;
		EXPECT_EQ(n.classVerbosity, c.read_int(ns, "class_verbosity", nDefault.classVerbosity)) << path;
		EXPECT_EQ(e.lcMinNodeIdDiff, c.read_int("GeneralConfiguration", "LC_min_nodeid_diff", eDefault.lcMinNodeIdDiff))
			<< path;
		EXPECT_EQ(e.classVerbosity, c.read_int(es, "class_verbosity", eDefault.classVerbosity)) << path;
	}
}

TEST(graphslam_options, deciders_load_from_the_engine_ini_file)
{
	const std::string path = ::testing::TempDir() + "gv_deciders_test.ini";
	{
		std::ofstream f(path);
		f << "[NodeRegistrationDeciderParameters]\nregistration_max_distance = 0.3\n"
			 "[gridvector_matcher]\nmax_rms = 0.09\n[GridVectorERD]\nmax_loop_candidates = 2\n";
	}
	CGridVectorNRD nrd;
	nrd.loadParams(path);
	EXPECT_DOUBLE_EQ(nrd.options().registrationMaxDistance, 0.3);
	EXPECT_DOUBLE_EQ(nrd.config().matcher.maxRms, 0.09);
	CGridVectorERD erd;
	erd.loadParams(path);
	EXPECT_EQ(erd.options().maxLoopCandidates, 2);
	std::ofstream(path) << "[gridvector_matcher]\nmax_rsm = 0.09\n";
	EXPECT_THROW(nrd.loadParams(path), std::runtime_error);
	std::remove(path.c_str());
	EXPECT_THROW(nrd.loadParams(path), std::runtime_error);
}

TEST(graphslam_registry, lists_and_creates_grid_vector_and_mrpt_deciders)
{
	DeciderRegistry reg;
	for (const char* n : {"CGridVectorNRD", "CFixedIntervalsNRD", "CICPCriteriaNRD", "CEmptyNRD"})
		EXPECT_TRUE(reg.checkRegistrationDeciderExists(n, "node")) << n;
	for (const char* n : {"CGridVectorERD", "CICPCriteriaERD", "CLoopCloserERD", "CEmptyERD"})
		EXPECT_TRUE(reg.checkRegistrationDeciderExists(n, "edge")) << n;
	EXPECT_FALSE(reg.checkRegistrationDeciderExists("CGridVectorNRD", "edge"));
	std::unique_ptr<mrpt::graphslam::deciders::CNodeRegistrationDecider<DeciderRegistry::graph_t>> nrd(
		reg.node_regs_map.at("CGridVectorNRD")());
	EXPECT_NE(dynamic_cast<CGridVectorNRD*>(nrd.get()), nullptr);
	std::unique_ptr<mrpt::graphslam::deciders::CEdgeRegistrationDecider<DeciderRegistry::graph_t>> erd(
		reg.edge_regs_map.at("CGridVectorERD")());
	EXPECT_NE(dynamic_cast<CGridVectorERD*>(erd.get()), nullptr);
}

TEST(pose_fusion, information_weighted_and_singular_directions_kept)
{
	PoseEstimate a{TPose2D(1, 0, 0), Eigen::Matrix3d::Identity()};
	PoseEstimate b{TPose2D(2, 1, 0.2), Eigen::Matrix3d::Zero()};
	b.information(0, 0) = 3;  // b constrains x only
	const auto f = fuse(a, b);
	EXPECT_NEAR(f.mean.x, 1.75, 1e-9);
	EXPECT_NEAR(f.mean.y, 0, 1e-9);
	EXPECT_NEAR(f.mean.phi, 0, 1e-9);
	EXPECT_NEAR(f.information(0, 0), 4, 1e-12);
	EXPECT_TRUE(validInformation(f.information));
	Eigen::Matrix3d bad = Eigen::Matrix3d::Identity();
	bad(2, 2) = -1;
	EXPECT_FALSE(validInformation(bad));
}

namespace
{
// Node 1 after MRPT's levmarq on two edges 0 -> 1 (node 0 fixed at the origin).
TPose2D optimisedOverTwoEdges(const PoseEstimate& a, const PoseEstimate& b, bool errorFrame)
{
	mrpt::graphs::CNetworkOfPoses2DInf g;
	g.root = 0;
	g.nodes[0] = CPose2D();
	g.nodes[1] = CPose2D(a.mean);
	g.insertEdge(0, 1, toConstraint(a, errorFrame));
	g.insertEdge(0, 1, toConstraint(b, errorFrame));
	mrpt::graphslam::TResultInfoSpaLevMarq info;
	mrpt::containers::yaml params;
	params["max_iterations"] = 100;
	mrpt::graphslam::optimize_graph_spa_levmarq(g, info, nullptr, params);
	return g.nodes.at(1).asTPose();
}
}  // namespace

// MRPT's edge error is inv(EDGE) (+) inv(P1) (+) P2 (Eq. 21's): an NRD edge fused over the
// relative pose's parameters must, once in the engine, optimise to that fusion, also when
// the two poses face opposite ways (a registration's translation/heading coupling kept).
TEST(pose_fusion, engine_edges_between_opposite_facing_poses_optimise_to_the_fusion)
{
	const PoseEstimate odometry{TPose2D(0.3, -0.1, M_PI - 0.2), Eigen::Vector3d(100, 100, 400).asDiagonal()};
	PoseEstimate match{TPose2D(0.32, -0.2, M_PI - 0.19), Eigen::Matrix3d::Zero()};
	match.information << 2e4, 0, 8e3, 0, 20, 0, 8e3, 0, 2e4;  // a corridor along y: strong x and phi, coupled
	const PoseEstimate fused = fuse(odometry, match);
	const TPose2D rotated = optimisedOverTwoEdges(odometry, match, true);
	EXPECT_NEAR(rotated.x, fused.mean.x, 1e-3);
	EXPECT_NEAR(rotated.y, fused.mean.y, 1e-3);
	EXPECT_NEAR(rotated.phi, fused.mean.phi, 1e-4);
	// the unrotated information weighs the wrong directions: far from the fusion
	const TPose2D unrotated = optimisedOverTwoEdges(odometry, match, false);
	EXPECT_GT(std::hypot(unrotated.x - fused.mean.x, unrotated.y - fused.mean.y), 1e-2);
	// the engine's constraint is the fused one in the error's frame
	const auto c = toConstraint(fused, true);
	const Eigen::Matrix3d expected = gridvector::PoseGraph::errorFrameInformation(fused.information, fused.mean);
	EXPECT_TRUE(c.cov_inv.asEigen().isApprox(expected, 1e-12));
	EXPECT_NEAR(c.mean.x(), fused.mean.x, 1e-12);
}

// Observation-only stream (odometry, then scan) through NRD then ERD, as the engine calls them.
TEST(graphslam_deciders, nodes_follow_the_truth_better_than_odometry_and_edges_are_added)
{
	const Drive d;
	mrpt::graphs::CNetworkOfPoses2DInf graph;
	CGridVectorNRD nrd;
	CGridVectorERD erd;
	const auto cfg =
		ini("[NodeRegistrationDeciderParameters]\nregistration_max_distance = 0.5\n"
			"[EdgeRegistrationDeciderParameters]\nLC_min_nodeid_diff = 30\n"
			"[GridVectorERD]\nmatch_previous_node = true\n");
	nrd.loadOptions(cfg, "mem");
	erd.loadOptions(cfg, "mem");
	nrd.setGraphPtr(&graph);
	erd.setGraphPtr(&graph);
	std::vector<size_t> nodeStep(1, 0);  // the root has the first scan
	for (size_t i = 0; i < d.truth.size(); ++i)
		for (const auto& obs : {odometryAt(d.odometry[i]), scanAt(d.truth[i])})
		{
			const bool reg = nrd.updateState({}, {}, obs);
			erd.updateState({}, {}, obs);
			if (reg) nodeStep.push_back(i);
		}
	graph.dijkstra_nodes_estimate();
	ASSERT_GE(graph.nodeCount(), 8u);
	ASSERT_EQ(graph.nodeCount(), nodeStep.size());
	EXPECT_GT(nrd.stats().matched, nrd.stats().scans / 2);
	EXPECT_GT(graph.edgeCount(), graph.nodeCount());  // ERD edges on top of the chain
	EXPECT_GT(erd.stats().sequentialEdges, 0u);
	const size_t last = graph.nodeCount() - 1;
	const TPose2D t0 = d.truth[0], o0 = d.odometry[0];
	const double gvError = positionError(graph.nodes.at(last), d.truth[nodeStep[last]], t0);
	const double odoError =
		(CPose2D(d.odometry[nodeStep[last]]) - CPose2D(o0)).distanceTo(CPose2D(d.truth[nodeStep[last]]) - CPose2D(t0));
	EXPECT_LT(gvError, 0.1);
	EXPECT_LT(gvError, 0.5 * odoError);
	for (const auto& e : graph.edges)  // information from the matcher: positive definite
		EXPECT_GT(e.second.cov_inv.asEigen().determinant(), 0);
}

TEST(graphslam_recorder, scans_between_nodes_follow_odometry_from_their_node)
{
	RunRecorder rec;
	size_t known = 0;  // as in the engine: nodes appear at the scan's step, not the odometry's
	auto step = [&](const TPose2D& odo, size_t nodes) {
		rec.record({}, {}, odometryAt(odo), known);
		known = nodes;
		auto s = scanAt(TPose2D(0, 0, 0));
		s->timestamp = mrpt::Clock::fromDouble(double(rec.scanCount()) + 100);
		rec.record({}, {}, s, nodes);
	};
	step(TPose2D(5, 5, 0), 0);  // root scan
	step(TPose2D(5.3, 5, 0), 0);
	step(TPose2D(5.6, 5, 0), 2);  // first node registered at this scan
	step(TPose2D(5.6, 5.2, M_PI / 2), 2);
	RunRecorder::Nodes nodes;
	nodes[0] = CPose2D(0, 0, 0);
	nodes[1] = CPose2D(0.6, 0.1, 0);  // corrected
	const auto traj = rec.scanTrajectory(nodes);
	ASSERT_EQ(traj.size(), 4u);
	EXPECT_NEAR(traj[0].first, 100, 1e-6);
	EXPECT_NEAR(traj[1].second.x, 0.3, 1e-9);
	EXPECT_NEAR(traj[2].second.x, 0.6, 1e-9);
	EXPECT_NEAR(traj[2].second.y, 0.1, 1e-9);
	EXPECT_NEAR(traj[3].second.y, 0.3, 1e-9);
	EXPECT_NEAR(traj[3].second.phi, M_PI / 2, 1e-9);
	const auto n = rec.nodeTrajectory(nodes);
	ASSERT_EQ(n.size(), 2u);
	EXPECT_NEAR(n[1].first, 102, 1e-6);
}
