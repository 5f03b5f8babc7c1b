// gv-graphslam: MRPT's graphslam-engine (2D) with the grid-vector deciders
// registered next to MRPT's own; also writes a CGridVectorMap of the result.
//
//   gv-graphslam --2d -i INI -r RAWLOG [-g GT] -n CGridVectorNRD -e CGridVectorERD -o CLevMarqGSO
//   gv-graphslam --list-regs
#include "io/ErrorText.h"
#include "map/MapExport.h"
#include "graphslam/DeciderOptions.h"
#include "graphslam/CGridVectorERD.h"
#include "graphslam/CGridVectorNRD.h"
#include <gridvector/graphslam/DeciderRegistry.h>
#include "graphslam/EngineOptions.h"
#include "graphslam/GroundTruthIndex.h"
#include "graphslam/IniKeys.h"
#include "graphslam/RunRecorder.h"
#include "em/SelfCheck.h"
#include "common/ArgParser.h"
#include "io/Counted.h"
#include "io/AtomicFile.h"
#include "io/FileBytes.h"
#include "io/IniLayout.h"
#include "io/Progress.h"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/containers/yaml.h>
#include <mrpt/graphslam/CGraphSlamEngine.h>
#include <mrpt/graphslam/levmarq.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/filesystem.h>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <vector>

using namespace gridvector;
using namespace gridvector::graphslam;
using graph_t = mrpt::graphs::CNetworkOfPoses2DInf;

namespace
{
struct Settings
{
	std::string ini, rawlog, groundTruth, nodeReg, edgeReg, optimizer, outDir;
	bool finalOptimization = true, quiet = false;
};

const char* const kNodeReg = "CGridVectorNRD";
const char* const kEdgeReg = "CGridVectorERD";
// The grid-vector deciders optimise Eq. 22 themselves (and MRPT's engine re-derives the nodes by Dijkstra
// after every step anyway): CLevMarqGSO's work is overwritten and only costs time. Other deciders need it.
const char* const kGridVectorOptimizer = "CEmptyGSO";
const char* const kOptimizer = "CLevMarqGSO";

// MRPT's graphslam-engine spells its value options with one dash.
std::vector<std::string> longOptions(int argc, char** argv)
{
	static const std::map<std::string, std::string> shortToLong = {
		{"-i", "--ini-file"}, {"-r", "--rawlog"},    {"-g", "--ground-truth"}, {"-n", "--node-reg"},
		{"-e", "--edge-reg"}, {"-o", "--optimizer"}, {"-h", "--help"}};
	std::vector<std::string> out;
	for (int i = 0; i < argc; ++i)
	{
		const auto it = shortToLong.find(argv[i]);
		out.push_back(i > 0 && it != shortToLong.end() ? it->second : argv[i]);
	}
	return out;
}

void declare(io::ArgParser& a)
{
	a.option("ini-file", "INI", "graphslam-engine .ini (-i)", io::ArgParser::kRequired);
	a.option("rawlog", "RAWLOG", "rawlog, either format, plain or gzip (-r)", io::ArgParser::kRequired);
	a.option("ground-truth", "GT.txt", "ground truth for the engine's SLAM metric (-g)", "none");
	a.option("node-reg", "NRD", "node registration decider (-n)", kNodeReg);
	a.option("edge-reg", "ERD", "edge registration decider (-e)", kEdgeReg);
	a.option("optimizer", "GSO", "graph optimizer (-o); CLevMarqGSO gives the grid-vector deciders the same result, slower",
			 "CEmptyGSO with CGridVectorNRD, else CLevMarqGSO");
	a.option("output-dir", "DIR", "results directory", "output_dir_fname of the .ini");
	a.flag("2d", "2D graph of CPosePDFGaussianInf constraints (the only kind supported)");
	a.flag("3d", "not supported: rejected");
	a.flag("disable-visuals", "accepted for compatibility: gv-graphslam always runs headless");
	a.flag("list-regs", "list all registration deciders");
	a.flag("list-node-regs", "list node registration deciders");
	a.flag("list-edge-regs", "list edge registration deciders");
	a.flag("list-optimizers", "list graph optimizers");
	a.flag("no-final-optimization",
		   "trajectory/map from the engine's last node estimates instead of a final full "
		   "Levenberg-Marquardt pass over the whole graph");
	a.flag("quiet", "no progress, no engine messages and no summary: errors only");
}

/** Returns true if a listing was asked for (and printed). */
bool listings(const io::ArgParser& a, const DeciderRegistry& reg)
{
	bool any = false;
	if (a.has("list-regs")) reg.dumpRegistrarsToConsole("all"), any = true;
	if (a.has("list-node-regs")) reg.dumpRegistrarsToConsole("node"), any = true;
	if (a.has("list-edge-regs")) reg.dumpRegistrarsToConsole("edge"), any = true;
	if (a.has("list-optimizers")) reg.dumpOptimizersToConsole(), any = true;
	return any;
}

Settings settingsFrom(const io::ArgParser& a, const DeciderRegistry& reg)
{
	if (a.has("3d")) a.fail("only 2D graph SLAM (--2d) is supported");
	if (!a.positional().empty()) a.fail("unexpected argument '" + a.positional()[0] + "'");
	Settings s;
	s.ini = a.get("ini-file");
	s.rawlog = a.get("rawlog");
	if (s.ini.empty()) a.fail("missing -i INI");
	if (s.rawlog.empty()) a.fail("missing -r RAWLOG");
	s.groundTruth = a.get("ground-truth");
	s.nodeReg = a.get("node-reg", kNodeReg);
	s.edgeReg = a.get("edge-reg", kEdgeReg);
	s.optimizer = a.get("optimizer", s.nodeReg == kNodeReg ? kGridVectorOptimizer : kOptimizer);
	if (!reg.checkRegistrationDeciderExists(s.nodeReg, "node") || !reg.node_regs_map.count(s.nodeReg))
		a.fail("unknown node registration decider '" + s.nodeReg + "'; --list-node-regs lists them");
	if (!reg.checkRegistrationDeciderExists(s.edgeReg, "edge") || !reg.edge_regs_map.count(s.edgeReg))
		a.fail("unknown edge registration decider '" + s.edgeReg + "'; --list-edge-regs lists them");
	if (!reg.checkOptimizerExists(s.optimizer) || !reg.optimizers_map.count(s.optimizer))
		a.fail("unknown optimizer '" + s.optimizer + "'; --list-optimizers lists them");
	s.outDir = a.get("output-dir");
	s.finalOptimization = !a.has("no-final-optimization");
	s.quiet = a.has("quiet");
	return s;
}

void requireFile(const std::string& path, const char* what)
{
	if (!mrpt::system::fileExists(path)) throw std::runtime_error(path + ": no such " + std::string(what));
	io::checkReadableFile(path);  // a directory passed MRPT's fileExists and failed in the engine as "unknown error"
}

/** Feeds every rawlog entry to the engine; returns the number of entries. */
size_t feed(const std::string& rawlog, mrpt::graphslam::CGraphSlamEngine<graph_t>& engine, RunRecorder& rec,
			std::optional<GroundTruthIndex>& gt, bool quiet)
{
	mrpt::io::CFileGZInputStream in;
	if (!in.open(rawlog)) throw std::runtime_error(rawlog + ": cannot open");
	io::Progress progress("graph SLAM: rawlog entries", quiet);  // the share of the (compressed) file read
	const double bytes = double(std::max<uint64_t>(1, in.getTotalBytesCount()));
	auto arch = mrpt::serialization::archiveFrom(in);
	mrpt::obs::CActionCollection::Ptr action;
	mrpt::obs::CSensoryFrame::Ptr sf;
	mrpt::obs::CObservation::Ptr obs;
	size_t entry = 0, steps = 0;
	for (;;)
	{
		// CRawlog reports a corrupt entry on std::cerr and returns false: capture it
		std::ostringstream report;
		std::streambuf* cerrBuf = std::cerr.rdbuf(report.rdbuf());
		bool more = false;
		try
		{
			more = mrpt::obs::CRawlog::getActionObservationPairOrObservation(arch, action, sf, obs, entry);
		}
		catch (const std::exception& e)
		{
			report << e.what();
		}
		std::cerr.rdbuf(cerrBuf);
		if (!report.str().empty())
			throw std::runtime_error(rawlog + ": entry " + std::to_string(entry) + ": unreadable (" +
									 oneLineError(report.str(), 160) + ")");
		if (!more) break;
		if (!action && !sf && !obs) continue;
		if (!obs && (!action || !sf)) continue;  // the engine needs both halves of a pair
		if (gt) gt->beforeStep(rawlog, entry);
		engine._execGraphSlamStep(action, sf, obs, entry);
		if (gt) gt->afterStep(obs != nullptr, entry);
		rec.record(action, sf, obs, engine.getGraph().nodeCount());
		++steps;
		progress.update(std::min(1.0, double(in.getPosition()) / bytes), entry);
	}
	progress.done();
	if (steps == 0) throw std::runtime_error(rawlog + ": no rawlog entries");
	return steps;
}

size_t loopClosures(const graph_t& g, int minDiff)
{
	size_t n = 0;
	for (const auto& e : g.edges)
		if (std::abs(long(e.first.first) - long(e.first.second)) > minDiff) ++n;
	return n;
}

void writeGridVectorMap(const std::string& dir, const mrpt::maps::CGridVectorMap& map)
{
	map.saveToFile(dir + "/map.gvmap");
	MapExport::writeVectorsText(map.vectors(), dir + "/vectors.txt");
	MapExport::writeSvg(map.vectors(), dir + "/vectors.svg");
	MapExport::write3DScene(map.vectors(), map.getAsOccupancyGrid(), dir + "/map.3Dscene");
}

/** The engine's own outputs, as MRPT's graphslam-engine app writes them. */
void writeEngineOutputs(mrpt::graphslam::CGraphSlamEngine<graph_t>& engine, const EngineOptions& gc,
						const std::string& dir)
{
	engine.generateReportFiles(dir);
	if (gc.saveGraph)
	{
		const std::string path = dir + "/" + gc.graphName;
		engine.saveGraph(&path);
	}
	if (gc.saveMap)
	{
		auto grid = mrpt::maps::COccupancyGridMap2D::Create();
		engine.getMap(grid);
		grid->saveMetricMapRepresentationToFile(dir + "/" + gc.mapName);
	}
}

/** MRPT 2.5's engine constructor wrongly calls the 2D graph class untested
 * (it compares "CPosePDFGaussianInf" with "mrpt::poses::CPosePDFGaussianInf")
 * and then waits for a key: give it end-of-file instead of the terminal. */
class StdinFromDevNull
{
   public:
	StdinFromDevNull() : saved_(dup(0))
	{
		const int null = open("/dev/null", O_RDONLY);
		if (null >= 0) dup2(null, 0), close(null);
	}
	~StdinFromDevNull()
	{
		if (saved_ >= 0) dup2(saved_, 0), close(saved_);
	}

   private:
	int saved_;
};

/** --quiet: MRPT's engine and deciders print their start-up messages (before their logging level
 * can be set), an INFO-level exception dump about a missing RGB-D info file and, when destroyed,
 * their timing tables, all on stdout, and on a terminal the colour codes of their log lines on
 * stderr. While this lives, stdout and stderr go to /dev/null (errors are thrown, and reported by
 * runTool once it is gone). */
class QuietOutput
{
   public:
	explicit QuietOutput(bool on)
	{
		if (!on) return;
		std::fflush(stdout), std::cout.flush(), std::fflush(stderr), std::cerr.flush();
		const int null = open("/dev/null", O_WRONLY);
		if (null < 0) return;
		for (int fd : {1, 2})
			if ((saved_[fd - 1] = dup(fd)) >= 0) dup2(null, fd);
		close(null);
	}
	~QuietOutput()
	{
		std::fflush(stdout), std::cout.flush(), std::fflush(stderr), std::cerr.flush();
		for (int fd : {1, 2})
			if (saved_[fd - 1] >= 0) dup2(saved_[fd - 1], fd), close(saved_[fd - 1]);
	}
	QuietOutput(const QuietOutput&) = delete;
	QuietOutput& operator=(const QuietOutput&) = delete;

   private:
	int saved_[2] = {-1, -1};
};

/** Checks the grid-vector sections before the engine reads them: errors
 * thrown inside the engine's constructor reach us mangled by MRPT_END. */
GridVectorConfig validateGridVectorSections(const mrpt::config::CConfigFileBase& ini, const Settings& s)
{
	if (s.nodeReg == "CGridVectorNRD") NodeDeciderOptions().load(ini, s.ini);
	if (s.edgeReg == "CGridVectorERD") EdgeDeciderOptions().load(ini, s.ini);
	GridVectorConfig c;
	try
	{
		c.loadFromConfigFile(ini, "gridvector", s.ini);
	}
	catch (const std::invalid_argument& e)
	{
		throw std::runtime_error(e.what());  // names the file
	}
	return c;
}

/** What a run says at the end: its summary line and, with the grid-vector deciders, the self-check. */
struct RunResult
{
	std::string summary;
	std::optional<SelfCheckVerdict> verdict;
};

/** The self-check of gv-em-slam (em/SelfCheck.h) on the online EM-SLAM behind CGridVectorNRD: its registrations,
 * its final graph's fit and edges (the map-based signals judge unconverged EM only, and there is no EM loop). */
std::optional<SelfCheckVerdict> selfCheck(const mrpt::graphslam::deciders::CNodeRegistrationDecider<graph_t>& nrd)
{
	const auto* g = dynamic_cast<const CGridVectorNRD*>(&nrd);
	if (!g || g->online().keyframes().size() < 2) return std::nullopt;
	const auto& slam = g->online();
	return judge(selfCheckEvidence(true, {slam.report()}, slam.keyframes().size(), poseGraphFit(slam.graph()), {}, {}));
}

/** Runs the engine. */
RunResult run(const Settings& s, DeciderRegistry& reg)
{
	const QuietOutput quiet(s.quiet);  // declared first: the engine and deciders are destroyed inside it
	requireFile(s.ini, "config file");
	{
		const std::vector<char> text = io::readFileBytes(s.ini);  // MRPT's reader skips what it cannot parse
		io::requireIniLayout(std::string(text.begin(), text.end()), s.ini);
	}
	requireFile(s.rawlog, "rawlog");
	std::optional<GroundTruthIndex> gt;
	if (!s.groundTruth.empty())
	{
		requireFile(s.groundTruth, "ground-truth file");
		gt.emplace(s.groundTruth, checkGroundTruthFile(s.groundTruth));
	}
	mrpt::config::CConfigFile ini(s.ini);
	if (gt) requireNavSimulGroundTruth(ini, s.ini);
	EngineOptions gc;
	gc.load(ini, s.ini);  // before the engine reads its keys loosely
	EdgeDeciderOptions lc;  // the summary's loop-closure threshold, read as CGridVectorERD reads it
	readSection(ini, EdgeDeciderOptions::sharedSection, false, s.ini, [&](auto&& v) { lc.visitShared(v); });
	const GridVectorConfig mapConfig = validateGridVectorSections(ini, s);
	const std::string dir = s.outDir.empty() ? gc.outputDir : s.outDir;
	io::OutputDirectory outDir(dir, "trajectory.txt");  // checked now, created when the engine has results

	// the engine does not own its deciders: they must outlive it
	std::unique_ptr<mrpt::graphslam::deciders::CNodeRegistrationDecider<graph_t>> nrd(reg.node_regs_map[s.nodeReg]());
	std::unique_ptr<mrpt::graphslam::deciders::CEdgeRegistrationDecider<graph_t>> erd(reg.edge_regs_map[s.edgeReg]());
	std::unique_ptr<mrpt::graphslam::optimizers::CGraphSlamOptimizer<graph_t>> gso(reg.optimizers_map[s.optimizer]());
	try
	{
		linkDeciders(*nrd, *erd);
	}
	catch (const std::invalid_argument& e)
	{
		throw std::runtime_error(std::string("-e ") + s.edgeReg + " -n " + s.nodeReg + ": " + e.what());
	}
	std::optional<StdinFromDevNull> noPause(std::in_place);
	// optional: destroyed before the marker is written, since its destructor writes timings.log
	std::optional<mrpt::graphslam::CGraphSlamEngine<graph_t>> engineHolder;
	engineHolder.emplace(s.ini, s.rawlog, s.groundTruth, nullptr, nrd.get(), erd.get(), gso.get());
	auto& engine = *engineHolder;
	noPause.reset();
	if (s.quiet)
		for (mrpt::system::COutputLogger* l :
			 {static_cast<mrpt::system::COutputLogger*>(&engine), static_cast<mrpt::system::COutputLogger*>(nrd.get()),
			  static_cast<mrpt::system::COutputLogger*>(erd.get()),
			  static_cast<mrpt::system::COutputLogger*>(gso.get())})
			l->setMinLoggingLevel(mrpt::system::LVL_ERROR);

	RunRecorder rec;
	const auto t0 = std::chrono::steady_clock::now();
	const size_t steps = feed(s.rawlog, engine, rec, gt, s.quiet);
	finishDeciders(*nrd, *erd);  // the grid-vector deciders' closing edge search and optimisation
	const auto verdict = selfCheck(*nrd);
	const double slamSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	writeEngineOutputs(engine, gc, outDir.create());

	graph_t graph = engine.getGraph();
	engineHolder.reset();  // the engine's last file (timings.log) before ours: the marker must be newest
	if (s.finalOptimization && graph.edgeCount() > 0)
	{
		mrpt::graphslam::TResultInfoSpaLevMarq info;
		mrpt::containers::yaml params;
		params["max_iterations"] = 100;
		mrpt::graphslam::optimize_graph_spa_levmarq(graph, info, nullptr, params);
	}
	io::writeTrajectory(dir + "/nodes.txt", rec.nodeTrajectory(graph.nodes));
	mrpt::maps::CGridVectorMap map;
	map.setConfig(mapConfig);
	rec.buildMap(graph.nodes, map);
	writeGridVectorMap(dir, map);
	io::writeTrajectory(outDir.markerPath(), rec.scanTrajectory(graph.nodes));  // last: with it the set is complete

	char summary[1024];
	std::snprintf(summary, sizeof summary, "gv-graphslam: %s + %s + %s: %s, %s, %s, %s (%s), %s; SLAM %.2f s -> %s/\n",
				  s.nodeReg.c_str(), s.edgeReg.c_str(), s.optimizer.c_str(),
				  io::counted(steps, "entry", "entries").c_str(), io::counted(rec.scanCount(), "scan").c_str(),
				  io::counted(graph.nodeCount(), "node").c_str(), io::counted(graph.edgeCount(), "edge").c_str(),
				  io::counted(loopClosures(graph, lc.lcMinNodeIdDiff), "loop closure").c_str(),
				  io::counted(map.vectors().size(), "map vector").c_str(), slamSeconds, dir.c_str());
	return {summary, verdict};
}
}  // namespace

int main(int argc, char** argv)
{
	io::ArgParser args("gv-graphslam", "--2d -i INI -r RAWLOG [-g GT] [-n NRD] [-e ERD] [-o GSO] [options]");
	declare(args);
	const auto argvLong = longOptions(argc, argv);
	std::vector<const char*> cargv;
	for (const auto& a : argvLong) cargv.push_back(a.c_str());
	return io::runTool(args, int(cargv.size()), cargv.data(), [&] {
		DeciderRegistry reg;
		if (listings(args, reg)) return 0;
		const Settings s = settingsFrom(args, reg);
		const RunResult r = run(s, reg);
		if (!s.quiet) std::fputs(r.summary.c_str(), stdout);
		if (!r.verdict) return 0;
		if (!s.quiet || !r.verdict->ok)  // --quiet: only a suspect run
			std::fprintf(stderr, "%s\n", verdictLine(*r.verdict).c_str());
		return r.verdict->ok ? 0 : 3;
	});
}
