#include "io/Progress.h"

#include <unistd.h>

#include <cstdio>

namespace gridvector::io
{
using Clock = std::chrono::steady_clock;

Progress::Progress(std::string label, bool quiet)
	: label_(std::move(label)), enabled_(!quiet && ::isatty(STDERR_FILENO)), start_(Clock::now()), last_(start_)
{}

Progress::~Progress() { done(); }

std::string Progress::line(const std::string& stage, double fraction, double elapsedSeconds)
{
	char buf[64];
	std::snprintf(buf, sizeof buf, "%5.1f%%", 100.0 * fraction);
	std::string s = stage.empty() ? std::string(buf) : stage + ": " + buf;
	if (fraction > 0.02 && fraction < 1.0)
	{
		std::snprintf(buf, sizeof buf, ", ETA %.0f s", elapsedSeconds * (1.0 - fraction) / fraction);
		s += buf;
	}
	return s;
}

void Progress::update(double fraction, size_t count)
{
	draw(label_, label_ + " (" + std::to_string(count) + ")", fraction);
}

void Progress::show(const std::string& stage, size_t done, size_t total)
{
	draw(stage, stage + " " + std::to_string(done) + "/" + std::to_string(total),
		 total ? double(done) / double(total) : 1.0);
}

void Progress::show(const std::string& stage, double fraction) { draw(stage, stage, fraction); }

void Progress::draw(const std::string& stage, const std::string& text, double fraction)
{
	if (!enabled_) return;
	const auto now = Clock::now();
	if (stage != stage_) stage_ = stage, start_ = now;
	if (drawn_ && now - last_ < std::chrono::milliseconds(100) && fraction < 1.0) return;
	last_ = now;
	drawn_ = true;
	const double elapsed = std::chrono::duration<double>(now - start_).count();
	std::fprintf(stderr, "\r\033[K%s", line(text, fraction, elapsed).c_str());
	std::fflush(stderr);
}

void Progress::done()
{
	if (!enabled_ || !drawn_) return;
	std::fprintf(stderr, "\r\033[K");
	std::fflush(stderr);
	drawn_ = false;
}

}  // namespace gridvector::io
