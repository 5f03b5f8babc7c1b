#include <gridvector/io/Progress.h>

#include <unistd.h>

#include <cstdio>

namespace gridvector::io
{
Progress::Progress(std::string label, bool quiet)
	: label_(std::move(label)), enabled_(!quiet && ::isatty(STDERR_FILENO)), last_(std::chrono::steady_clock::now())
{
}

Progress::~Progress() { done(); }

void Progress::update(double fraction, size_t count)
{
	if (!enabled_) return;
	const auto now = std::chrono::steady_clock::now();
	if (drawn_ && now - last_ < std::chrono::milliseconds(100)) return;
	last_ = now;
	drawn_ = true;
	std::fprintf(stderr, "\r%s: %5.1f%% (%zu)   ", label_.c_str(), 100.0 * fraction, count);
	std::fflush(stderr);
}

void Progress::done()
{
	if (!enabled_ || !drawn_) return;
	std::fprintf(stderr, "\r%*s\r", int(label_.size() + 30), "");
	std::fflush(stderr);
	drawn_ = false;
}

}  // namespace gridvector::io
