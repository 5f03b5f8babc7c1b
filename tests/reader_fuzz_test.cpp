// Mutation fuzzing of every reader, in process: CARMEN logs, rawlogs (both layouts), .gvmap files
// and .ini files, mutated with extreme values, corrupt length fields, byte flips, insertions and
// truncations from a fixed seed. Every input must be read or rejected with one line naming the
// file ("FILE: problem", "FILE:LINE: problem") and nothing printed to stderr; no signal, no input over
// kSecondsPerInput, peak RSS under kMaxRssMb, address space capped at kAddressSpaceMb (a runaway allocation is a
// failure, not a rejection). Accepted logs go on through extraction and map insertion, accepted maps through their
// vectors: the geometry a reader lets through must not crash what follows.
//
// GV_FUZZ_INPUTS (default 12000, 3000 per format) and GV_FUZZ_SEED (default 1) set the corpus:
// the longer mode of doc/benchmarks.md is GV_FUZZ_INPUTS=200000.
#include "io/FileBytes.h"
#include "io/ObjectFile.h"
#include "io/RawlogReader.h"
#include "io/RawlogWriter.h"
#include <gridvector/GridVectorConfig.h>
#include <gridvector/io/LogReader.h>
#include <mrpt/maps/CGridVectorMap.h>

#include "extraction/VectorExtractor.h"
#include "io/CarmenReader.h"

#include <gtest/gtest.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

namespace fs = std::filesystem;
using namespace gridvector;

namespace
{
/** A hang: one input taking longer than this (the slowest valid one takes milliseconds) [s]. */
constexpr unsigned kSecondsPerInput = 10;
/** Address-space cap of the fuzzing process: a reader that sizes a buffer from a corrupt count fails. */
constexpr rlim_t kAddressSpaceMb = 3072;
/** Peak resident memory over the whole corpus. */
constexpr long kMaxRssMb = 500;

size_t envSize(const char* name, size_t def)
{
	const char* v = std::getenv(name);
	return v && *v ? size_t(std::strtoull(v, nullptr, 10)) : def;
}

fs::path workDir()
{
	static const fs::path d = [] {
		fs::path p = fs::temp_directory_path() / ("gv_fuzz_" + std::to_string(::getpid()));
		fs::create_directories(p);
		return p;
	}();
	return d;
}

using Bytes = std::vector<char>;

Bytes fileBytes(const fs::path& p)
{
	std::ifstream f(p, std::ios::binary);
	return Bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

void writeBytes(const fs::path& p, const Bytes& b)
{
	std::ofstream f(p, std::ios::binary | std::ios::trunc);
	f.write(b.data(), std::streamsize(b.size()));
}

// --- seeds ---------------------------------------------------------------------------------------

/** A robot in an 8 x 6 m room: PARAM lines, 12 FLASER scans of 181 beams, ODOM, ROBOTLASER1, RAWLASER1. */
std::string roomLog()
{
	std::ostringstream o;
	o << "# fuzz seed\nPARAM laser_front_laser_resolution 1.0\nPARAM robot_front_laser_max 50\n"
	  << "PARAM robot_frontlaser_offset 0.1\nPARAM robot_frontlaser_side_offset 0\n"
	  << "PARAM robot_frontlaser_angular_offset 0\nPARAM laser_front_laser_fov 180\n";
	char buf[64];
	const auto ranges = [&](double x, double y, double th) {
		std::string s;
		for (int i = 0; i < 181; i++)
		{
			const double a = th - M_PI / 2 + M_PI * i / 180, dx = std::cos(a), dy = std::sin(a);
			double r = 1e9;
			if (dx > 1e-9) r = std::min(r, (4 - x) / dx);
			if (dx < -1e-9) r = std::min(r, (-4 - x) / dx);
			if (dy > 1e-9) r = std::min(r, (3 - y) / dy);
			if (dy < -1e-9) r = std::min(r, (-3 - y) / dy);
			std::snprintf(buf, sizeof buf, " %.3f", r);
			s += buf;
		}
		return s;
	};
	for (int t = 0; t < 12; t++)
	{
		const double x = -2 + 0.15 * t, y = 0.3 * std::sin(t / 5.0), th = 0.12 * t, ts = 1000 + 0.2 * t;
		char pose[160];
		std::snprintf(pose, sizeof pose, " %.4f %.4f %.4f %.4f %.4f %.4f %.6f fuzz %.6f", x, y, th, x, y, th, ts, ts);
		o << "FLASER 181" << ranges(x, y, th) << pose << "\n";
		std::snprintf(pose, sizeof pose, "ODOM %.4f %.4f %.4f 0.1 0 0 %.6f fuzz %.6f\n", x, y, th, ts + 0.05,
					  ts + 0.05);
		o << pose;
		if (t % 4 == 0)
		{
			std::snprintf(pose, sizeof pose, " 0 %.4f %.4f %.4f %.4f %.4f %.4f 0.1 0 1 1 1 %.6f fuzz %.6f", x, y, th, x,
						  y, th, ts + 0.1, ts + 0.1);
			o << "ROBOTLASER1 0 -1.5708 3.14159 0.0174533 50 0.01 0 181" << ranges(x, y, th) << pose << "\n";
			std::snprintf(pose, sizeof pose, " 0 %.6f fuzz %.6f", ts + 0.12, ts + 0.12);
			o << "RAWLASER1 0 -1.5708 3.14159 0.0174533 50 0.01 0 181" << ranges(x, y, th) << pose << "\n";
		}
	}
	return o.str();
}

struct Seeds
{
	Bytes carmen;
	std::vector<Bytes> rawlogs;  //!< observation-only, sensory frames (uncompressed)
	Bytes gvmapRaw;  //!< the serialised map, uncompressed
	std::vector<std::string> inis;
};

Bytes toBytes(const std::string& s) { return Bytes(s.begin(), s.end()); }

const Seeds& seeds()
{
	static const Seeds s = [] {
		Seeds out;
		out.carmen = toBytes(roomLog());
		const io::LogData log = io::parseCarmenLog(out.carmen, "seed.log");
		for (auto format : {io::RawlogFormat::Observations, io::RawlogFormat::SensoryFrames})
		{
			const fs::path p = workDir() / "seed.rawlog";
			io::writeRawlog(p.string(), log, {format, false});
			out.rawlogs.push_back(fileBytes(p));
		}
		mrpt::maps::CGridVectorMap map;
		for (const auto& r : log.scans)
			map.insertObservation(*r.scan, mrpt::poses::CPose3D(mrpt::poses::CPose2D(r.logPose)));
		const fs::path m = workDir() / "seed.gvmap";
		map.saveToFile(m.string());
		out.gvmapRaw = io::readFileBytes(m.string());
		std::ostringstream ini;
		GridVectorConfig().dumpAsIni(ini);
		out.inis = {ini.str(),
					"[gridvector_grid]\nresolution = 0.05\nhalf_width = 2\n[gridvector_occupancy]\nresolution = 0.1\n"
					"[gridvector_mstep]\nmax_iterations = 5\nsequential_window = 5\n"};
		return out;
	}();
	return s;
}

// --- mutations -----------------------------------------------------------------------------------

const char* const kExtremeTokens[] = {"0",
									  "-0",
									  "1",
									  "-1",
									  "1e300",
									  "-1e308",
									  "1e-300",
									  "nan",
									  "inf",
									  "-inf",
									  "2147483647",
									  "2147483648",
									  "4294967296",
									  "1073741824",
									  "268435456",
									  "100001",
									  "0x1p3",
									  "1e6",
									  "-1e6",
									  "1e15",
									  "3.5e38",
									  "1e39",
									  "",
									  "1e-6",
									  "6.2832",
									  "360",
									  "1000.5",
									  "-90",
									  "99999999999999999999"};
const uint32_t kExtremeU32[] = {0,
								1,
								2,
								0x7fffffff,
								0x80000000,
								0xffffffff,
								1u << 30,
								1u << 28,
								100001,
								65536,
								0x7fc00000 /* float NaN */,
								0x7f800000 /* float inf */,
								0x7e967699 /* 1e38f */,
								0xbf800000 /* -1.0f */,
								0x88,
								0x80};
const double kExtremeDoubles[] = {std::nan(""), INFINITY, -INFINITY, 1e308, -1e308, 1e15,
								  -1e15,        1e-300,   0.0,       -1.0,  1e6};

using Rng = std::mt19937_64;
size_t pick(Rng& r, size_t n) { return n ? size_t(r() % n) : 0; }

/** Token-level and byte-level mutations of text (a CARMEN log, an .ini). */
Bytes mutateText(const Bytes& seed, Rng& r)
{
	std::string s(seed.begin(), seed.end());
	const int ops = 1 + int(pick(r, 3));
	for (int k = 0; k < ops && !s.empty(); ++k)
	{
		const size_t at = pick(r, s.size());
		const size_t b = s.find_last_of(" \n=\t", at) == std::string::npos ? 0 : s.find_last_of(" \n=\t", at) + 1;
		size_t e = s.find_first_of(" \n\t", b);
		if (e == std::string::npos) e = s.size();
		switch (pick(r, 9))
		{
			case 0:
			case 1:
			case 2:  // a token becomes an extreme value (a count, a range, a pose, a PARAM, an .ini value)
				s.replace(b, e - b, kExtremeTokens[pick(r, std::size(kExtremeTokens))]);
				break;
			case 3:  // a token disappears or doubles
				if (pick(r, 2))
					s.erase(b, e - b + (e < s.size()));
				else
					s.insert(b, s.substr(b, e - b) + " ");
				break;
			case 4:  // a byte changes
				s[at] = char(r());
				break;
			case 5:  // bytes inserted
				s.insert(at, std::string(1 + pick(r, 8), char(r())));
				break;
			case 6:  // truncated
				s.resize(at);
				break;
			case 7:  // a line duplicated, deleted or without its separator
			{
				const size_t lb = s.rfind('\n', at) == std::string::npos ? 0 : s.rfind('\n', at) + 1;
				size_t le = s.find('\n', at);
				le = le == std::string::npos ? s.size() : le + 1;
				const size_t sel = pick(r, 3);
				if (sel == 0) s.insert(lb, s.substr(lb, le - lb));
				if (sel == 1) s.erase(lb, le - lb);
				if (sel == 2)
				{
					const size_t eq = s.find('=', lb);
					if (eq < le) s[eq] = ' ';
				}
				break;
			}
			default:  // a beam count (FLASER n / ROBOTLASER n) changes
			{
				const size_t f = s.find("FLASER 181", pick(r, s.size()));
				if (f != std::string::npos) s.replace(f + 7, 3, kExtremeTokens[pick(r, std::size(kExtremeTokens))]);
			}
		}
	}
	return toBytes(s);
}

/** Field-level and byte-level mutations of MRPT serialisations. */
Bytes mutateBinary(const Bytes& seed, Rng& r)
{
	Bytes b = seed;
	const int ops = 1 + int(pick(r, 2));
	for (int k = 0; k < ops && b.size() > 8; ++k)
	{
		const size_t at = pick(r, b.size() - 8);
		switch (pick(r, 8))
		{
			case 0:
			case 1:  // a length field: a small little-endian count (1..100000) becomes an extreme value
			{
				for (size_t tries = 0; tries < 64; ++tries)
				{
					const size_t p = pick(r, b.size() - 4);
					uint32_t v;
					std::memcpy(&v, &b[p], 4);
					if (v >= 1 && v <= 100000)
					{
						const uint32_t x = kExtremeU32[pick(r, std::size(kExtremeU32))];
						std::memcpy(&b[p], &x, 4);
						break;
					}
				}
				break;
			}
			case 2:  // any 4 bytes: an extreme int or float
			{
				const uint32_t x = kExtremeU32[pick(r, std::size(kExtremeU32))];
				std::memcpy(&b[at], &x, 4);
				break;
			}
			case 3:  // any 8 bytes: an extreme double (poses, vector ends, likelihood options)
			{
				const double x = kExtremeDoubles[pick(r, std::size(kExtremeDoubles))];
				std::memcpy(&b[at], &x, 8);
				break;
			}
			case 4:
				b[at] = char(r());
				break;
			case 5:
				b[at] ^= char(1u << pick(r, 8));
				break;
			case 6:  // truncated
				b.resize(at);
				break;
			default:  // bytes inserted or removed
				if (pick(r, 2))
					b.insert(b.begin() + long(at), 1 + pick(r, 8), char(r()));
				else
					b.erase(b.begin() + long(at), b.begin() + long(std::min(b.size(), at + 1 + pick(r, 8))));
		}
	}
	return b;
}

void writeGzip(const fs::path& p, const Bytes& b)
{
	mrpt::io::CFileGZOutputStream gz;
	ASSERT_TRUE(gz.open(p.string()));
	gz.Write(b.data(), b.size());
}

// --- the readers and what follows them ----------------------------------------------------------

char current[96] = "";  //!< the input being read, for the signal handlers

struct Tally
{
	size_t inputs = 0, accepted = 0, rejected = 0;
	std::vector<std::string> failures;  //!< empty: every rejection was one line naming the file
	int stderrFd =
		-1;  //!< stderr goes to this file while fuzzing: a reader must not print (a tool's error is one line)
	off_t stderrSize = 0;
};

/** What was written to stderr since the last call (MRPT prints some problems before it throws). */
std::string newStderr(Tally& t)
{
	std::fflush(stderr);
	const off_t end = ::lseek(t.stderrFd, 0, SEEK_END);
	if (end <= t.stderrSize) return "";
	std::string text(size_t(end - t.stderrSize), '\0');
	(void)!::pread(t.stderrFd, text.data(), text.size(), t.stderrSize);
	t.stderrSize = end;
	return text;
}

/** Downstream of an accepted log: the first scans through extraction and map insertion. */
void useLog(const io::LogData& log)
{
	const GridVectorConfig cfg;
	const VectorExtractor ex(cfg.extraction, cfg.grid);
	mrpt::maps::CGridVectorMap map;
	size_t n = 0;
	for (const auto& r : log.scans)
	{
		if (n++ == 4) break;
		ex.extract(*r.scan);
		const mrpt::math::TPose2D p = r.hasLogPose ? r.logPose : r.odometry;
		map.insertObservation(*r.scan, mrpt::poses::CPose3D(mrpt::poses::CPose2D(p)));
	}
}

/** One input: `read` must return or throw std::runtime_error/invalid_argument whose text is one line
 * starting with "name:". Anything else is a failure. */
template <class Read>
void check(Tally& t, const std::string& kind, size_t i, const std::string& name, Read&& read)
{
	t.inputs++;
	std::snprintf(current, sizeof current, "%s #%zu", kind.c_str(), i);
	::alarm(kSecondsPerInput);
	try
	{
		read();
		t.accepted++;
	}
	catch (const std::bad_alloc&)
	{
		t.failures.push_back(kind + " #" + std::to_string(i) + ": std::bad_alloc (a runaway allocation)");
	}
	catch (const std::exception& e)
	{
		const std::string msg = e.what();
		t.rejected++;
		if (msg.find('\n') != std::string::npos || msg.rfind(name + ":", 0) != 0)
			t.failures.push_back(kind + " #" + std::to_string(i) + ": not one line naming " + name + ": " +
								 msg.substr(0, 300));
	}
	catch (...)
	{
		t.failures.push_back(kind + " #" + std::to_string(i) + ": a non-std exception");
	}
	::alarm(0);
	const std::string printed = newStderr(t);
	if (!printed.empty())
		t.failures.push_back(kind + " #" + std::to_string(i) + ": printed to stderr: " + printed.substr(0, 300));
}

int realStderr = 2;  //!< the terminal's stderr while fd 2 goes to the capture file

void onSignal(int sig)
{
	char msg[200];
	const int n = std::snprintf(msg, sizeof msg, "reader_fuzz_test: signal %d on %s\n", sig, current);
	(void)!::write(realStderr, msg, size_t(n));
	std::_Exit(128 + sig);
}

void onAlarm(int)
{
	char msg[200];
	const int n = std::snprintf(msg, sizeof msg, "reader_fuzz_test: %s took longer than the limit (a hang)\n", current);
	(void)!::write(realStderr, msg, size_t(n));
	std::_Exit(3);
}

long peakRssMb()
{
	rusage u{};
	::getrusage(RUSAGE_SELF, &u);
	return u.ru_maxrss / 1024;
}

/** GV_FUZZ_DUMP=kind#index (as a failure names it) writes that input to GV_FUZZ_DUMP_FILE (default
 * fuzz_input.bin) before it is read: a crash's input, to reproduce with the tools. */
void dumpIfAsked(const char* kind, size_t i, const Bytes& b)
{
	const char* want = std::getenv("GV_FUZZ_DUMP");
	if (!want || std::string(want) != std::string(kind) + " #" + std::to_string(i)) return;
	const char* file = std::getenv("GV_FUZZ_DUMP_FILE");
	writeBytes(file ? file : "fuzz_input.bin", b);
}

void fuzzCarmen(Tally& t, Rng& r, size_t n)
{
	for (size_t i = 0; i < n; ++i)
	{
		const Bytes b = mutateText(seeds().carmen, r);
		dumpIfAsked("carmen", i, b);
		if (i % 8 == 0)  // through the file path too: readLog (format sniffing, line limit), gzip or not
		{
			const fs::path p = workDir() / (i % 16 == 0 ? "m.log.gz" : "m.log");
			i % 16 == 0 ? writeGzip(p, b) : writeBytes(p, b);
			check(t, "carmen", i, p.string(), [&] { useLog(io::readLog(p.string())); });
		}
		else
			check(t, "carmen", i, "m.log", [&] { useLog(io::parseCarmenLog(b, "m.log")); });
	}
}

void fuzzRawlog(Tally& t, Rng& r, size_t n)
{
	for (size_t i = 0; i < n; ++i)
	{
		const Bytes b = mutateBinary(seeds().rawlogs[i % 2], r);
		dumpIfAsked("rawlog", i, b);
		if (i % 8 == 0)
		{
			const fs::path p = workDir() / "m.rawlog";
			writeBytes(p, b);
			check(t, "rawlog", i, p.string(), [&] { useLog(io::readLog(p.string())); });
		}
		else
			check(t, "rawlog", i, "m.rawlog", [&] { useLog(io::parseRawlog(b, "m.rawlog")); });
	}
}

void fuzzGvmap(Tally& t, Rng& r, size_t n)
{
	const fs::path p = workDir() / "m.gvmap";
	Bytes gz;
	{
		writeGzip(p, seeds().gvmapRaw);
		gz = fileBytes(p);
	}
	for (size_t i = 0; i < n; ++i)
	{
		if (i % 4 == 0)  // the compressed file itself: the gzip layer and its CRC
			writeBytes(p, mutateBinary(gz, r));
		else  // the serialisation, compressed with a valid CRC
			writeGzip(p, mutateBinary(seeds().gvmapRaw, r));
		check(t, "gvmap", i, p.string(), [&] {
			mrpt::maps::CGridVectorMap map;
			io::readObjectFile(p.string(), map);
			double s = 0;
			for (const auto& v : map.vectors()) s += v.pStatic() + v.length();
			(void)s;
		});
	}
}

void fuzzIni(Tally& t, Rng& r, size_t n)
{
	const fs::path p = workDir() / "m.ini";
	for (size_t i = 0; i < n; ++i)
	{
		writeBytes(p, mutateText(toBytes(seeds().inis[i % 2]), r));
		check(t, "ini", i, p.string(), [&] {
			GridVectorConfig c;
			c.loadFromFile(p.string());
		});
	}
}
}  // namespace

TEST(ReaderFuzz, EveryReaderRejectsMutantsWithOneLineAndNoRunaway)
{
	const rlimit as{kAddressSpaceMb << 20, kAddressSpaceMb << 20};
	ASSERT_EQ(::setrlimit(RLIMIT_AS, &as), 0);
	std::signal(SIGALRM, onAlarm);
	for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGABRT, SIGILL}) std::signal(sig, onSignal);
	const size_t total = envSize("GV_FUZZ_INPUTS", 12000);
	Rng rng(envSize("GV_FUZZ_SEED", 1));
	seeds();
	const auto t0 = std::chrono::steady_clock::now();
	Tally t;
	const std::string errPath = (workDir() / "stderr.txt").string();
	t.stderrFd = ::open(errPath.c_str(), O_RDWR | O_CREAT | O_TRUNC, 0600);
	ASSERT_GE(t.stderrFd, 0);
	std::fflush(stderr);
	const int savedStderr = ::dup(2);
	realStderr = savedStderr;
	::dup2(t.stderrFd, 2);
	struct Kind
	{
		const char* name;
		void (*run)(Tally&, Rng&, size_t);
	};
	for (const Kind k :
		 {Kind{"carmen", fuzzCarmen}, Kind{"rawlog", fuzzRawlog}, Kind{"gvmap", fuzzGvmap}, Kind{"ini", fuzzIni}})
	{
		const size_t before = t.inputs, acc = t.accepted;
		k.run(t, rng, total / 4);
		std::printf("%-7s %zu inputs, %zu accepted\n", k.name, t.inputs - before, t.accepted - acc);
	}
	std::fflush(stderr);
	::dup2(savedStderr, 2);
	realStderr = 2;
	::close(savedStderr);
	::close(t.stderrFd);
	const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	std::printf("fuzz: %zu inputs (seed %zu) in %.1f s: %zu accepted, %zu rejected, %zu failures, peak RSS %ld MB\n",
				t.inputs, envSize("GV_FUZZ_SEED", 1), secs, t.accepted, t.rejected, t.failures.size(), peakRssMb());
	for (size_t k = 0; k < std::min<size_t>(t.failures.size(), 20); ++k) ADD_FAILURE() << t.failures[k];
	EXPECT_TRUE(t.failures.empty());
	EXPECT_GE(t.inputs, std::min<size_t>(total, 10000) / 4 * 4);
	EXPECT_LT(peakRssMb(), kMaxRssMb);
	fs::remove_all(workDir());
}
