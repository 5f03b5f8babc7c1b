// gv-bench-log: make a SLAM benchmark (OUT.log + OUT.ref.txt) from a corrected
// CARMEN log, as ../shared/bench/mkbench.py does, without Python.
#include "common/ArgParser.h"
#include "io/Counted.h"
#include "io/TextParsing.h"
#include "sim/BenchmarkLog.h"

#include <iostream>

using namespace gridvector;

int main(int argc, char** argv)
{
	io::ArgParser args("gv-bench-log",
					   "IN-corrected.log[.gz] OUT_PREFIX [options]   (writes OUT_PREFIX.log, OUT_PREFIX.ref.txt)");
	const sim::BenchmarkOptions defaults;  // mkbench.py's
	args.option("seed", "N", "random seed", std::to_string(defaults.seed));
	args.option("sigma-t", "X", "relative translation noise", io::shortestText(defaults.noise.sigmaT));
	args.option("sigma-r", "RAD", "rotation noise per step", io::shortestText(defaults.noise.sigmaR));
	args.option("drift-deg-per-m", "X", "systematic yaw drift", io::shortestText(defaults.noise.driftDegPerM));
	args.option("dt", "S", "synthetic seconds between scans", io::shortestText(defaults.dt));
	args.flag("quiet", "no summary line");
	return io::runTool(args, argc, argv, [&] {
		args.requirePositional(2, 2);
		sim::BenchmarkOptions o = defaults;
		o.seed = args.getInt("seed", defaults.seed, 0, 0x7fffffffffffffffL);
		o.noise.sigmaT = args.getDouble("sigma-t", o.noise.sigmaT);
		o.noise.sigmaR = args.getDouble("sigma-r", o.noise.sigmaR);
		o.noise.driftDegPerM = args.getDouble("drift-deg-per-m", o.noise.driftDegPerM);
		o.dt = args.getDouble("dt", o.dt);
		if (o.noise.sigmaT < 0 || o.noise.sigmaR < 0) args.fail("noise levels must be >= 0");
		if (o.dt <= 0) args.fail("--dt must be > 0");
		const auto s = sim::makeBenchmarkLog(args.positional()[0], args.positional()[1], o);
		if (!args.has("quiet"))
			std::cout << "gv-bench-log: " << io::counted(s.scans, "scan") << " from " << args.positional()[0]
					  << " (seed " << o.seed << ") -> " << s.logPath << ", " << s.refPath << "\n";
		return 0;
	});
}
