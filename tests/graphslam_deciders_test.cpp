// Grid-vector registration deciders for MRPT's graphslam-engine: options, registry, behaviour.
#include "graphslam/CGridVectorERD.h"
#include "graphslam/CGridVectorNRD.h"
#include <gridvector/graphslam/DeciderRegistry.h>
#include "posegraph/PoseGraph.h"
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
#include <set>

#include "graphslam_ini_files.h"
#include "room_loop.h"

using namespace gridvector::graphslam;
using gridvector::online::OnlineEmSlam;
using mrpt::math::TPose2D;
using mrpt::poses::CPose2D;

namespace
{
mrpt::config::CConfigFileMemory ini(const std::string& text) { return mrpt::config::CConfigFileMemory(text); }

mrpt::obs::CObservation::Ptr scanAt(const TPose2D& truth)
{
	auto s = mrpt::obs::CObservation2DRangeScan::Create(gvtest::castScan(truth, gvtest::clutteredRoom(), {}, 361, M_PI, 20));
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
	EXPECT_EQ(NodeDeciderOptions().classVerbosity, 1);
	EdgeDeciderOptions e;
	EXPECT_EQ(e.lcMinNodeIdDiff, 30);
	EXPECT_EQ(e.classVerbosity, 1);
}

TEST(graphslam_options, shared_sections_tolerate_other_deciders_keys)
{
	NodeDeciderOptions n;  // MRPT's node deciders' keys: not CGridVectorNRD's (its nodes are the keyframes)
	EXPECT_NO_THROW(n.load(ini("[NodeRegistrationDeciderParameters]\nregistration_max_distance = 0.2 // m\n"
							   "registration_max_angle = 30\nclass_verbosity = 0\n"),
						   "t.ini"));
	EXPECT_EQ(n.classVerbosity, 0);
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

// The deciders' own sections take no key: a file written for the old deciders (session 15 and before)
// says so instead of having its keys silently ignored.
TEST(graphslam_options, own_sections_take_no_key)
{
	EXPECT_EQ(loadError<EdgeDeciderOptions>("[GridVectorERD]\nmax_distance = 4\n"),
			  "a.ini: unknown key 'max_distance' in section [GridVectorERD]");
	EXPECT_EQ(loadError<NodeDeciderOptions>("[GridVectorNRD]\nuse_odometry = true\n"),
			  "a.ini: unknown key 'use_odometry' in section [GridVectorNRD]");
	EXPECT_EQ(loadError<NodeDeciderOptions>("[GridVectorNRD]\n"), "");
}

TEST(graphslam_options, bad_values_are_errors_naming_file_section_key_value_and_why)
{
	EXPECT_EQ(loadError<NodeDeciderOptions>("[NodeRegistrationDeciderParameters]\nclass_verbosity = 7\n"),
			  "a.ini: [NodeRegistrationDeciderParameters] class_verbosity = '7' must be in 0..3");
	EXPECT_EQ(loadError<EdgeDeciderOptions>("[GeneralConfiguration]\nLC_min_nodeid_diff = 0\n"),
			  "a.ini: [GeneralConfiguration] LC_min_nodeid_diff = '0' must be >= 1");
	// MRPT's read_int made this 3 without a word
	EXPECT_EQ(loadError<EdgeDeciderOptions>("[EdgeRegistrationDeciderParameters]\nLC_min_nodeid_diff = 3O\n"),
			  "a.ini: [EdgeRegistrationDeciderParameters] LC_min_nodeid_diff = '3O' is not an integer");
	// other deciders' keys in the shared sections stay theirs to read
	EXPECT_EQ(loadError<EdgeDeciderOptions>("[EdgeRegistrationDeciderParameters]\nICP_goodness_thresh = 0.o5\n"), "");
	EXPECT_EQ(loadError<NodeDeciderOptions>("[NodeRegistrationDeciderParameters]\nregistration_max_angle = nan\n"),
			  "");
}

TEST(graphslam_options, values_end_as_in_mrpts_graphslam_files)
{
	EdgeDeciderOptions e;
	e.load(ini("[GeneralConfiguration]\nLC_min_nodeid_diff = 12;\n[EdgeRegistrationDeciderParameters]\nclass_verbosity "
			   "= 0 // debug\n"),
		   "t.ini");
	EXPECT_EQ(e.lcMinNodeIdDiff, 12);
	EXPECT_EQ(e.classVerbosity, 0);
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
		EXPECT_EQ(n.classVerbosity, c.read_int(NodeDeciderOptions::sharedSection, "class_verbosity", 1)) << path;
		EXPECT_EQ(e.lcMinNodeIdDiff, c.read_int("GeneralConfiguration", "LC_min_nodeid_diff", eDefault.lcMinNodeIdDiff))
			<< path;
		EXPECT_EQ(e.classVerbosity, c.read_int(EdgeDeciderOptions::sharedSection, "class_verbosity", 1)) << path;
	}
}

TEST(graphslam_options, deciders_load_from_the_engine_ini_file)
{
	const std::string path = ::testing::TempDir() + "gv_deciders_test.ini";
	std::ofstream(path) << "[gridvector_matcher]\nmax_rms = 0.09\n[gridvector_mstep]\nkeyframe_distance = 0.3\n";
	CGridVectorNRD nrd;
	nrd.loadParams(path);
	EXPECT_DOUBLE_EQ(nrd.config().matcher.maxRms, 0.09);
	EXPECT_DOUBLE_EQ(nrd.config().mstep.keyframeDistance, 0.3);
	CGridVectorERD erd;
	EXPECT_NO_THROW(erd.loadParams(path));
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
	EXPECT_NO_THROW(linkDeciders(*nrd, *erd));
}

// CGridVectorERD's edges are CGridVectorNRD's online EM-SLAM's: with another node decider, or none
// linked, it says so instead of running without edges.
TEST(graphslam_registry, the_grid_vector_edge_decider_needs_the_grid_vector_node_decider)
{
	DeciderRegistry reg;
	std::unique_ptr<mrpt::graphslam::deciders::CNodeRegistrationDecider<DeciderRegistry::graph_t>> icp(
		reg.node_regs_map.at("CICPCriteriaNRD")());
	std::unique_ptr<mrpt::graphslam::deciders::CEdgeRegistrationDecider<DeciderRegistry::graph_t>> icpEdges(
		reg.edge_regs_map.at("CICPCriteriaERD")());
	CGridVectorERD erd;
	EXPECT_THROW(linkDeciders(*icp, erd), std::invalid_argument);
	EXPECT_NO_THROW(linkDeciders(*icp, *icpEdges));  // MRPT's own pair: nothing to link
	mrpt::graphs::CNetworkOfPoses2DInf graph;
	erd.setGraphPtr(&graph);
	EXPECT_THROW(erd.updateState({}, {}, scanAt(TPose2D(0, 0, 0))), std::logic_error);
	CGridVectorNRD nrd;
	EXPECT_FALSE(finishDeciders(*icp, erd));
}

namespace
{
/** The Drive (or any truth/odometry pair) through NRD then ERD, as the engine calls them, observation-only
 * format (odometry, then scan). Returns the scan index of every node. */
std::vector<size_t> runDeciders(const std::vector<TPose2D>& truth, const std::vector<TPose2D>& odometry,
								CGridVectorNRD& nrd, CGridVectorERD& erd, mrpt::graphs::CNetworkOfPoses2DInf& graph)
{
	const auto cfg = ini("[GeneralConfiguration]\nLC_min_nodeid_diff = 30\n");
	nrd.loadOptions(cfg, "mem");
	erd.loadOptions(cfg, "mem");
	nrd.setGraphPtr(&graph);
	erd.setGraphPtr(&graph);
	linkDeciders(nrd, erd);
	std::vector<size_t> nodeScan(1, 0);  // the root has the first scan
	for (size_t i = 0; i < truth.size(); ++i)
		for (const auto& obs : {odometryAt(odometry[i]), scanAt(truth[i])})
		{
			const bool reg = nrd.updateState({}, {}, obs);
			erd.updateState({}, {}, obs);
			if (reg) nodeScan.push_back(i);
		}
	return nodeScan;
}

/** The registration edges of `graph` (all edges less one odometry edge per consecutive pair), by key. */
std::multiset<std::pair<uint32_t, uint32_t>> registrationEdges(const mrpt::graphs::CNetworkOfPoses2DInf& graph)
{
	std::multiset<std::pair<uint32_t, uint32_t>> out;
	for (const auto& e : graph.edges) out.insert({uint32_t(e.first.first), uint32_t(e.first.second)});
	for (uint32_t k = 1; k < graph.nodeCount(); ++k)
	{
		const auto it = out.find({k - 1, k});
		EXPECT_NE(it, out.end()) << "no odometry edge " << k - 1 << " -> " << k;
		if (it != out.end()) out.erase(it);
	}
	return out;
}
}  // namespace

// Sec. 6 through the engine's interfaces: every keyframe of the online EM-SLAM a node at its estimate,
// the odometry edges and the registration edges of Eq. 22 in the graph.
TEST(graphslam_deciders, nodes_are_the_online_keyframes_and_the_graph_is_eq22s)
{
	const Drive d;
	mrpt::graphs::CNetworkOfPoses2DInf graph;
	CGridVectorNRD nrd;
	CGridVectorERD erd;
	const auto nodeScan = runDeciders(d.truth, d.odometry, nrd, erd, graph);
	const OnlineEmSlam& slam = nrd.online();
	ASSERT_GE(graph.nodeCount(), 20u);  // 0.2 m keyframes along 6.5 m and a turn
	ASSERT_EQ(graph.nodeCount(), slam.keyframes().size());
	EXPECT_EQ(nodeScan, slam.keyframes());
	EXPECT_GT(nrd.stats().registered, nrd.stats().scans / 2);
	const CPose2D origin(slam.keyframePoses()[0]);
	for (size_t k = 0; k < graph.nodeCount(); ++k)
		EXPECT_LT(graph.nodes.at(k).distanceTo(CPose2D(slam.keyframePoses()[k]) - origin), 1e-9) << k;
	std::multiset<std::pair<uint32_t, uint32_t>> active;
	for (const auto& [key, c] : slam.constraints())
		if (!c.rejected) active.insert(key);
	EXPECT_EQ(registrationEdges(graph), active);
	EXPECT_GT(erd.stats().sequentialEdges, graph.nodeCount());  // a window of predecessors per keyframe
	const size_t last = graph.nodeCount() - 1;
	const double gvError = positionError(graph.nodes.at(last), d.truth[nodeScan[last]], d.truth[0]);
	const double odoError = positionError(CPose2D(d.odometry[nodeScan[last]]) - CPose2D(d.odometry[0]),
										  d.truth[nodeScan[last]], d.truth[0]);
	EXPECT_LT(gvError, 0.05);
	EXPECT_LT(gvError, 0.25 * odoError);
	for (const auto& e : graph.edges)  // odometry: positive definite; a registration: semi-definite
		EXPECT_GE(e.second.cov_inv.asEigen().determinant(), 0);
}

// A loop: the loop edges come into the graph, the nodes move to Eq. 22's optimum after it, and at the end
// (finishDeciders) the graph holds the final edges, whose optimum under MRPT's own Levenberg-Marquardt
// (what gv-graphslam and CLevMarqGSO run) is the online EM-SLAM's trajectory.
TEST(graphslam_deciders, a_loop_closes_and_mrpts_optimiser_keeps_the_online_optimum)
{
	const gvtest::RoomLoop loop;
	const auto& truth = loop.truth;
	const auto& odometry = loop.odometry;
	mrpt::graphs::CNetworkOfPoses2DInf graph;
	CGridVectorNRD nrd;
	CGridVectorERD erd;
	const auto nodeScan = runDeciders(truth, odometry, nrd, erd, graph);
	EXPECT_GT(erd.stats().loopClosures, 0u);  // edges between the laps
	ASSERT_TRUE(finishDeciders(nrd, erd));
	const OnlineEmSlam& slam = nrd.online();
	std::multiset<std::pair<uint32_t, uint32_t>> active;
	for (const auto& [key, c] : slam.constraints())
		if (!c.rejected) active.insert(key);
	EXPECT_EQ(registrationEdges(graph), active);
	auto g = graph;
	mrpt::graphslam::TResultInfoSpaLevMarq info;
	mrpt::containers::yaml params;
	params["max_iterations"] = 100;
	mrpt::graphslam::optimize_graph_spa_levmarq(g, info, nullptr, params);
	double worst = 0, worstOdo = 0;
	for (size_t k = 0; k < g.nodeCount(); ++k)
	{
		worst = std::max(worst, g.nodes.at(k).distanceTo(graph.nodes.at(k)));
		worstOdo = std::max(worstOdo, positionError(CPose2D(odometry[nodeScan[k]]) - CPose2D(odometry[0]),
													truth[nodeScan[k]], truth[0]));
		EXPECT_LT(positionError(g.nodes.at(k), truth[nodeScan[k]], truth[0]), 0.05) << k;
	}
	EXPECT_LT(worst, 0.01);  // MRPT's optimiser on the mirrored graph stays at the online optimum
	EXPECT_GT(worstOdo, 0.5);  // and the odometry was off: the loop mattered
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
