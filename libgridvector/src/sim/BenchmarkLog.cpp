#include "io/AtomicFile.h"
#include "io/Counted.h"
#include "io/CarmenReader.h"
#include "io/FileBytes.h"
#include "io/TextParsing.h"
#include "sim/BenchmarkLog.h"

#include <cstdio>
#include <string>
#include <vector>

namespace gridvector::sim
{
namespace
{
struct RefScan
{
	std::vector<std::string> ranges;  //!< verbatim, as mkbench.py copies them
	mrpt::math::TPose2D pose;
};

std::vector<RefScan> readFlaser(const std::string& path)
{
	const std::vector<char> text = io::readFileBytes(path);
	io::LineCursor cur(text);
	std::string_view line;
	io::TextPos pos{path, 0};
	std::vector<RefScan> out;
	while (cur.next(line))
	{
		pos.line = cur.lineNumber();
		const auto t = io::splitTokens(line);
		if (t.empty() || t[0] != "FLASER") continue;
		if (t.size() < 2) io::parseError(pos, "FLASER: no beam count");
		const size_t n = size_t(io::parseInt(t[1], pos, "FLASER beam count", 1, 100000));
		if (t.size() < 2 + n + 3)
			io::parseError(pos, "FLASER: expected at least " + io::counted(2 + n + 3, "field") + ", found " +
									std::to_string(t.size()));
		// mkbench.py reads the pose after the announced ranges: a wrong count would shift it silently
		if (!io::flaserFieldCountMatches(n, t.size()))
			io::parseError(pos, "FLASER: " + io::counted(n, "beam") + " announced: expected " +
									io::counted(2 + n + 9, "field") + ", found " + std::to_string(t.size()));
		RefScan s;
		for (size_t i = 0; i < n; i++)
		{
			if (io::parseDouble(t[2 + i], pos, "FLASER range " + std::to_string(i)) < 0)
				io::parseError(pos,
							   "FLASER range " + std::to_string(i) + " is " + std::string(t[2 + i]) + " (negative)");
			s.ranges.emplace_back(t[2 + i]);
		}
		s.pose = {io::parseDouble(t[2 + n], pos, "FLASER x"), io::parseDouble(t[3 + n], pos, "FLASER y"),
				  io::parseDouble(t[4 + n], pos, "FLASER theta")};
		out.push_back(std::move(s));
	}
	if (out.empty()) throw std::runtime_error(path + ": no FLASER lines (not a CARMEN laser log?)");
	return out;
}

std::string fmt(const char* f, double a, double b, double c, double t)
{
	char buf[256];
	std::snprintf(buf, sizeof buf, f, a, b, c, t, t);
	return buf;
}
}  // namespace

BenchmarkSummary makeBenchmarkLog(const std::string& in, const std::string& outPrefix, const BenchmarkOptions& opt)
{
	BenchmarkSummary sum{0, outPrefix + ".log", outPrefix + ".ref.txt"};
	for (const std::string& out : {sum.logPath, sum.refPath}) io::checkWritableFile(out);  // before the read
	const std::vector<RefScan> scans = readFlaser(in);
	sum.scans = scans.size();
	io::AtomicFile log(sum.logPath), ref(sum.refPath);
	std::ostream& L = log.stream();
	std::ostream& G = ref.stream();
	const size_t n = scans[0].ranges.size();
	char res[64];
	std::snprintf(res, sizeof res, "%g", n == 180 || n == 360 ? 180.0 / double(n) : 180.0 / double(n - 1));
	L << "# benchmark log: odometry synthesised from reference with noise\n"
	  << "PARAM laser_front_laser_resolution " << res << " bench 0\n"
	  << "PARAM laser_front_laser_fov 180 bench 0\n"
	  << "PARAM robot_front_laser_max 81.0 bench 0\n";
	Random rng(uint64_t(opt.seed));
	NoisyOdometry odo(opt.noise, rng);
	double t = 1100000000.0;
	for (const RefScan& s : scans)
	{
		const mrpt::math::TPose2D o = odo.step(s.pose);
		t += opt.dt;
		L << fmt("ODOM %.6f %.6f %.6f 0 0 0 %.6f bench %.6f\n", o.x, o.y, o.phi, t);
		L << "FLASER " << s.ranges.size();
		for (const auto& r : s.ranges) L << ' ' << r;
		L << fmt(" %.6f %.6f %.6f", o.x, o.y, o.phi, 0) << fmt(" %.6f %.6f %.6f %.6f bench %.6f\n", o.x, o.y, o.phi, t);
		char g[160];
		std::snprintf(g, sizeof g, "%.6f %.6f %.6f %.6f\n", t, s.pose.x, s.pose.y, s.pose.phi);
		G << g;
	}
	log.commit();
	ref.commit();
	return sum;
}

}  // namespace gridvector::sim
