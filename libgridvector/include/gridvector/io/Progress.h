// Progress line on stderr for long runs, only when stderr is a terminal.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace gridvector::io
{
class Progress
{
   public:
	/** Shows progress only if !quiet and stderr is a terminal. */
	Progress(std::string label, bool quiet);
	~Progress();
	/** fraction in [0,1]; redraws at most ~10 times a second. */
	void update(double fraction, size_t count);
	/** Clears the progress line. */
	void done();
	bool enabled() const { return enabled_; }

   private:
	std::string label_;
	bool enabled_;
	bool drawn_ = false;
	std::chrono::steady_clock::time_point last_;
};

}  // namespace gridvector::io
