// io::ArgParser and io::runTool, the main() every tool shares.
#include "common/ArgParser.h"

#include <gtest/gtest.h>

#include <functional>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace gridvector;

namespace
{
struct ToolRun
{
	int status = -1;
	std::string out, err;
	bool bodyRan = false;
};

/** runTool on "tool ARGS..." with a --n option, capturing stdout and stderr. */
ToolRun runTool(const std::vector<std::string>& args, const std::function<int(const io::ArgParser&)>& body)
{
	io::ArgParser parser("tool", "[--n N] [ARG]");
	parser.option("n", "N", "a number", "3");
	std::vector<const char*> argv{"tool"};
	for (const auto& a : args) argv.push_back(a.c_str());
	std::ostringstream out, err;
	ToolRun r;
	r.status = io::runTool(
		parser, int(argv.size()), argv.data(),
		[&] {
			r.bodyRan = true;
			return body(parser);
		},
		out, err);
	r.out = out.str();
	r.err = err.str();
	return r;
}

int ok(const io::ArgParser&) { return 0; }

const char* kMrptError =
	"==== MRPT exception ====\n"
	"Message: bad.rawlog: entry 3: unreadable\n"
	"Location: CRawlog.cpp:42\n"
	"Call stack backtrace:\n"
	"[0 ] 0x1234 mrpt::obs::CRawlog::read()\n";
}  // namespace

TEST(ArgParser, OptionsFlagsAndPositionals)
{
	io::ArgParser a("tool", "ARG");
	a.option("n", "N", "a number", "none");
	a.flag("quiet", "quiet");
	const char* argv[] = {"tool", "--n=3", "x", "--quiet", "--", "--y"};
	ASSERT_TRUE(a.parse(6, argv));
	EXPECT_EQ(a.getInt("n", 0, 0, 10), 3);
	EXPECT_TRUE(a.has("quiet"));
	EXPECT_EQ(a.positional(), (std::vector<std::string>{"x", "--y"}));
	EXPECT_THROW(a.getInt("n", 0, 4, 10), io::UsageError);
}

TEST(ArgParser, UsageListsEveryOptionWithItsDefault)
{
	io::ArgParser a("tool", "ARG");
	a.option("repeat", "N", "passes", "5");
	a.option("input", "LOG", "the log", io::ArgParser::kRequired);
	a.flag("quiet", "no progress");
	const std::string u = a.usage();
	const auto row = [](const std::string& left, const std::string& help) {
		return left + std::string(26 - left.size(), ' ') + help + "\n";  // the help in column 27
	};
	EXPECT_NE(u.find(row("  --repeat N", "passes (default: 5)")), std::string::npos) << u;
	EXPECT_NE(u.find(row("  --input LOG", "the log (required)")), std::string::npos) << u;
	EXPECT_NE(u.find(row("  --quiet", "no progress")), std::string::npos) << u;  // a flag: off unless given
	EXPECT_NE(u.find("  --help "), std::string::npos) << u;
	EXPECT_NE(u.find("  --version "), std::string::npos) << u;
	// the parser accepts exactly what it lists
	for (const char* opt : {"--repeat=1", "--input=x", "--quiet", "--version", "--help"})
	{
		io::ArgParser b = a;
		const char* argv[] = {"tool", opt};
		EXPECT_NO_THROW(b.parse(2, argv)) << opt;
	}
	const char* argv[] = {"tool", "--samples=2"};
	EXPECT_THROW(a.parse(2, argv), io::UsageError);
}

TEST(RunTool, HelpPrintsUsageOnStdoutAndReturnsZero)
{
	const ToolRun r = runTool({"--help"}, [](const io::ArgParser&) { return 7; });
	EXPECT_EQ(r.status, 0);
	EXPECT_FALSE(r.bodyRan);
	EXPECT_EQ(r.out.rfind("usage: tool [--n N] [ARG]\n", 0), 0u) << r.out;
	EXPECT_NE(r.out.find("--n N"), std::string::npos);
	EXPECT_EQ(r.err, "");
}

TEST(RunTool, BodysStatusPassedThrough)
{
	for (int status : {0, 1, 3, 42})
	{
		const ToolRun r = runTool({"--n", "5", "x"}, [&](const io::ArgParser& a) {
			EXPECT_EQ(a.get("n"), "5");
			EXPECT_EQ(a.positional().at(0), "x");
			return status;
		});
		EXPECT_TRUE(r.bodyRan);
		EXPECT_EQ(r.status, status);
		EXPECT_EQ(r.out, "");
		EXPECT_EQ(r.err, "");
	}
}

TEST(RunTool, UsageErrorIsOneLineAndStatusTwo)
{
	// from parsing: the body does not run
	ToolRun r = runTool({"--peeple", "3"}, ok);
	EXPECT_FALSE(r.bodyRan);
	EXPECT_EQ(r.status, 2);
	EXPECT_EQ(r.err, "tool: unknown option --peeple (see --help)\n");
	EXPECT_EQ(r.out, "");
	// from the body: the program named once
	r = runTool({"--n", "x"}, [](const io::ArgParser& a) { return int(a.getInt("n", 0, 0, 9)); });
	EXPECT_TRUE(r.bodyRan);
	EXPECT_EQ(r.status, 2);
	EXPECT_EQ(r.err, "tool: --n needs an integer, got 'x' (see --help)\n");
	r = runTool({"a", "b"}, [](const io::ArgParser& a) { return a.requirePositional(0, 1), 0; });
	EXPECT_EQ(r.status, 2);
	EXPECT_EQ(r.err, "tool: unexpected argument 'b' (see --help)\n");
}

TEST(RunTool, OtherErrorIsOneLineAndStatusOne)
{
	const auto fails = [](const io::ArgParser&) -> int { throw std::runtime_error("in.log:3: no scan"); };
	// every tool's convention: "PROG: FILE: problem"
	ToolRun r = runTool({}, fails);
	EXPECT_EQ(r.status, 1);
	EXPECT_EQ(r.err, "tool: in.log:3: no scan\n");
	EXPECT_EQ(r.out, "");
	// a message that already names the program names it once
	r = runTool({}, [](const io::ArgParser&) -> int { throw std::runtime_error("tool: in.log: empty"); });
	EXPECT_EQ(r.err, "tool: in.log: empty\n");

	// an MRPT exception: its message alone, without the backtrace
	const auto mrpt = [](const io::ArgParser&) -> int { throw std::runtime_error(kMrptError); };
	r = runTool({}, mrpt);
	EXPECT_EQ(r.status, 1);
	EXPECT_EQ(r.err, "tool: bad.rawlog: entry 3: unreadable\n");
}

TEST(RunTool, OneLineUsageErrors)
{
	const ToolRun r = runTool({"a\n\nb", "c"}, [](const io::ArgParser& a) { return a.requirePositional(0, 0), 0; });
	EXPECT_EQ(r.status, 2);
	EXPECT_EQ(r.err, "tool: unexpected argument 'a b' (see --help)\n");
}

TEST(RunTool, NeverACrash)
{
	ToolRun r = runTool({}, [](const io::ArgParser&) -> int { throw 42; });
	EXPECT_EQ(r.status, 1);
	EXPECT_EQ(r.err, "tool: unknown error\n");
	r = runTool({}, [](const io::ArgParser&) -> int { throw std::bad_alloc(); });
	EXPECT_EQ(r.status, 1);
	EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
	// --help with a bad rest of the line is a usage error
	r = runTool({"--help", "--n"}, ok);
	EXPECT_EQ(r.status, 2);
	EXPECT_EQ(r.err, "tool: option --n needs a value N (see --help)\n");
	EXPECT_EQ(r.out, "");
	EXPECT_FALSE(r.bodyRan);
}

// What CLI11 decides under the adapter, pinned: the tools' words and their reading of a command line.
TEST(ArgParser, ValuesFlagsAndNumbersAsTheToolsReadThem)
{
	const auto parsed = [](std::vector<const char*> argv) {
		io::ArgParser a("tool", "ARG");
		a.option("n", "N", "a number", "3");
		a.flag("quiet", "quiet");
		argv.insert(argv.begin(), "tool");
		a.parse(int(argv.size()), argv.data());
		return a;
	};
	EXPECT_EQ(parsed({"--n", "-1"}).get("n"), "-1") << "a negative number is a value";
	EXPECT_EQ(parsed({"--n=--x"}).get("n"), "--x");
	EXPECT_EQ(parsed({"--n", "1", "--n", "2"}).get("n"), "2") << "the last one given";
	EXPECT_EQ(parsed({"-5", "-", "-2.5"}).positional(), (std::vector<std::string>{"-5", "-", "-2.5"}));
	EXPECT_FALSE(parsed({}).has("n"));
	EXPECT_EQ(parsed({}).get("n", "d"), "d");
	const auto error = [&](std::vector<const char*> argv) {
		try
		{
			parsed(argv);
		}
		catch (const io::UsageError& e)
		{
			return std::string(e.what());
		}
		return std::string("accepted");
	};
	EXPECT_EQ(error({"--quiet=true"}), "tool: option --quiet takes no value (see --help)");
	EXPECT_EQ(error({"--n", "--quiet"}), "tool: option --n needs a value N (see --help)") << "an option is no value";
	EXPECT_EQ(error({"--n="}), "tool: option --n needs a value N (see --help)");
	EXPECT_EQ(error({"-q"}), "tool: unknown option -q (see --help)");
	EXPECT_EQ(error({"--bogus=1", "x"}), "tool: unknown option --bogus (see --help)");
	EXPECT_EQ(error({"x", "--", "--bogus"}), "accepted");
}
