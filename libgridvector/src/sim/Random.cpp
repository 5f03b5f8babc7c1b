#include "sim/Random.h"

#include <cmath>
#include <vector>

namespace gridvector::sim
{
void Random::initGenrand(uint32_t s)
{
	mt_[0] = s;
	for (int i = 1; i < 624; i++) mt_[i] = 1812433253u * (mt_[i - 1] ^ (mt_[i - 1] >> 30)) + uint32_t(i);
	mti_ = 624;
}

Random::Random(uint64_t seed)
{
	std::vector<uint32_t> key;
	do
	{
		key.push_back(uint32_t(seed & 0xFFFFFFFFu));
		seed >>= 32;
	} while (seed);
	// init_by_array (Matsumoto & Nishimura, as in CPython's _randommodule.c)
	initGenrand(19650218u);
	int i = 1;
	size_t j = 0;
	for (size_t k = std::max<size_t>(624, key.size()); k; k--)
	{
		mt_[i] = (mt_[i] ^ ((mt_[i - 1] ^ (mt_[i - 1] >> 30)) * 1664525u)) + key[j] + uint32_t(j);
		i++, j++;
		if (i >= 624) mt_[0] = mt_[623], i = 1;
		if (j >= key.size()) j = 0;
	}
	for (int k = 623; k; k--)
	{
		mt_[i] = (mt_[i] ^ ((mt_[i - 1] ^ (mt_[i - 1] >> 30)) * 1566083941u)) - uint32_t(i);
		i++;
		if (i >= 624) mt_[0] = mt_[623], i = 1;
	}
	mt_[0] = 0x80000000u;
	mti_ = 624;
}

void Random::twist()
{
	constexpr uint32_t upper = 0x80000000u, lower = 0x7fffffffu, matrixA = 0x9908b0dfu;
	for (int k = 0; k < 624; k++)
	{
		const uint32_t y = (mt_[k] & upper) | (mt_[(k + 1) % 624] & lower);
		mt_[k] = mt_[(k + 397) % 624] ^ (y >> 1) ^ ((y & 1) ? matrixA : 0);
	}
	mti_ = 0;
}

uint32_t Random::next32()
{
	if (mti_ >= 624) twist();
	uint32_t y = mt_[mti_++];
	y ^= y >> 11;
	y ^= (y << 7) & 0x9d2c5680u;
	y ^= (y << 15) & 0xefc60000u;
	y ^= y >> 18;
	return y;
}

double Random::uniform()
{
	const uint32_t a = next32() >> 5, b = next32() >> 6;
	return (a * 67108864.0 + b) * (1.0 / 9007199254740992.0);
}

int Random::uniformInt(int lo, int hi) { return lo + int(uniform() * double(hi - lo + 1)); }

double Random::gauss(double mu, double sigma)
{
	double z;
	if (haveNext_)
	{
		z = next_;
		haveNext_ = false;
	}
	else
	{
		const double x2pi = uniform() * (2.0 * M_PI);
		const double g2rad = std::sqrt(-2.0 * std::log(1.0 - uniform()));
		z = std::cos(x2pi) * g2rad;
		next_ = std::sin(x2pi) * g2rad;
		haveNext_ = true;
	}
	return mu + z * sigma;
}

}  // namespace gridvector::sim
