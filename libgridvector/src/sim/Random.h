// Seeded random numbers that are the same on every platform: MT19937 seeded and
// sampled exactly like CPython's random module (random.Random(seed).random() and
// .gauss()), so gv-bench-log reproduces mkbench.py's noise draw for draw.
#pragma once

#include <array>
#include <cstdint>

namespace gridvector::sim
{
class Random
{
   public:
	/** As random.Random(seed) in Python (init_by_array of the seed's 32-bit words). */
	explicit Random(uint64_t seed);

	uint32_t next32();
	/** Uniform in [0, 1) with 53 random bits (Python's random()). */
	double uniform();
	double uniform(double a, double b) { return a + (b - a) * uniform(); }
	/** Integer uniform in [lo, hi]. */
	int uniformInt(int lo, int hi);
	/** Normal(mu, sigma) by Python's random.gauss (Box-Muller, the second value cached). */
	double gauss(double mu, double sigma);
	bool chance(double p) { return uniform() < p; }

   private:
	void initGenrand(uint32_t s);
	void twist();
	std::array<uint32_t, 624> mt_{};
	int mti_ = 625;
	bool haveNext_ = false;
	double next_ = 0;
};

}  // namespace gridvector::sim
