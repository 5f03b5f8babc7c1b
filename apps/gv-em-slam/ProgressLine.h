// One progress line with an ETA on stderr, only when stderr is a terminal.
#pragma once

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>

namespace gridvector::app
{
class ProgressLine
{
   public:
	explicit ProgressLine(bool quiet) : enabled_(!quiet && ::isatty(STDERR_FILENO)) {}
	~ProgressLine() { clear(); }

	void show(const std::string& label, size_t done, size_t total)
	{
		show(label + " " + std::to_string(done) + "/" + std::to_string(total),
			 total ? double(done) / double(total) : 1.0);
	}

	/** fraction in [0,1] of the stage `label`; ETA from the stage's own pace. */
	void show(const std::string& label, double fraction)
	{
		if (!enabled_) return;
		const auto now = std::chrono::steady_clock::now();
		if (label != label_) label_ = label, start_ = now;
		if (drawn_ && now - last_ < std::chrono::milliseconds(100) && fraction < 1.0) return;
		last_ = now;
		drawn_ = true;
		const double el = std::chrono::duration<double>(now - start_).count();
		char eta[32] = "";
		if (fraction > 0.02 && fraction < 1.0) std::snprintf(eta, sizeof eta, ", ETA %.0f s", el * (1 - fraction) / fraction);
		std::fprintf(stderr, "\r\033[K%s: %5.1f%%%s", label.c_str(), 100.0 * fraction, eta);
		std::fflush(stderr);
	}

	void clear()
	{
		if (!enabled_ || !drawn_) return;
		std::fprintf(stderr, "\r\033[K");
		std::fflush(stderr);
		drawn_ = false;
	}

   private:
	bool enabled_;
	bool drawn_ = false;
	std::string label_;
	std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace gridvector::app
