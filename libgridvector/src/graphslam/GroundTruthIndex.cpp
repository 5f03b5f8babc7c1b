#include "graphslam/GroundTruthIndex.h"
#include "io/Counted.h"
#include "io/TextParsing.h"

#include <mrpt/system/string_utils.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace gridvector::graphslam
{
namespace
{
bool isGroundTruthLine(const std::string& line)
{
	std::vector<std::string> tokens;
	std::istringstream fields(line);
	for (std::string t; std::getline(fields, t, ' ');)
		if (!t.empty()) tokens.push_back(t);
	bool numbers = tokens.size() == 4;
	for (const auto& t : tokens)
	{
		char* end = nullptr;
		std::strtod(t.c_str(), &end);
		numbers = numbers && end && *end == '\0';
	}
	return numbers;
}
}  // namespace

size_t checkGroundTruthFile(const std::string& path)
{
	std::ifstream in(path);  // as the engine reads it: not through gzip
	if (!in) throw std::runtime_error(path + ": cannot read ground-truth file");
	size_t n = 0;
	for (std::string line; std::getline(in, line);)
	{
		if (!line.empty() && line.back() == '\r') line.pop_back();
		if (!isGroundTruthLine(line))
			throw std::runtime_error(path + ":" + std::to_string(n + 1) +
									 ": ground-truth lines must be 't x y theta' (4 numbers separated by spaces)");
		++n;
	}
	if (n == 0) throw std::runtime_error(path + ": no ground-truth poses");
	return n;
}

void requireNavSimulGroundTruth(const mrpt::config::CConfigFileBase& ini, const std::string& iniPath)
{
	// the key and default CGraphSlamEngine::loadParams reads; "rgbd_tum" throws "Not Implemented Yet",
	// any other value leaves the ground truth unread
	const std::string format = ini.read_string("GeneralConfiguration", "ground_truth_file_format", "NavSimul", false);
	if (!mrpt::system::strCmpI(format, "NavSimul"))
		throw std::runtime_error(iniPath + ": [GeneralConfiguration] ground_truth_file_format = '" +
								 io::printableToken(format) +
								 "': MRPT 2.5's graphslam engine reads ground truth (-g) as NavSimul only");
}

void GroundTruthIndex::beforeStep(const std::string& rawlog, size_t rawlogEntry) const
{
	if (index_ < poses_) return;
	throw std::runtime_error(path_ + ": " + io::counted(poses_, "ground-truth pose") + ", the engine reads pose " +
							 std::to_string(index_ + 1) + " at entry " + std::to_string(rawlogEntry) + " of " + rawlog +
							 " (one pose per scan)");
}

void GroundTruthIndex::afterStep(bool observation, size_t rawlogEntry)
{
	if (observationOnly_ < 0) observationOnly_ = observation ? 1 : 0;
	if (observationOnly_ == 0 || rawlogEntry % 2 == 0) ++index_;  // CGraphSlamEngine::_execGraphSlamStep, NavSimul
}

}  // namespace gridvector::graphslam
