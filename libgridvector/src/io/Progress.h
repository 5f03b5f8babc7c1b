// Progress line on stderr for long runs (stage, done/total, percent, ETA),
// only when stderr is a terminal and not --quiet.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace gridvector::io
{
class Progress
{
   public:
	/** Shows progress only if !quiet and stderr is a terminal; `label` names
	 * the stage update() reports. */
	explicit Progress(bool quiet) : Progress("", quiet) {}
	Progress(std::string label, bool quiet);
	~Progress();
	Progress(const Progress&) = delete;
	Progress& operator=(const Progress&) = delete;

	/** fraction in [0,1] of the default stage, `count` items so far. */
	void update(double fraction, size_t count);
	/** `done` of `total` items of `stage` ("stage 120/910 (13.2%), ETA 4 s"). */
	void show(const std::string& stage, size_t done, size_t total);
	/** fraction in [0,1] of `stage`; the ETA is measured from the stage's own start. */
	void show(const std::string& stage, double fraction);
	/** Clears the progress line. */
	void done();
	bool enabled() const { return enabled_; }

	/** The text of one progress line (no control characters). */
	static std::string line(const std::string& stage, double fraction, double elapsedSeconds);

   private:
	void draw(const std::string& stage, const std::string& text, double fraction);
	std::string label_, stage_;
	bool enabled_;
	bool drawn_ = false;
	std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace gridvector::io
