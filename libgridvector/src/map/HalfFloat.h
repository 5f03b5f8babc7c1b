// IEEE 754 binary16 ("half float"): the 2-byte storage of a cell's counts in the compact map (Eq. 2).
#pragma once

#include <cstdint>
#include <cstring>

namespace gridvector
{
/** binary16 of a finite non-negative or negative float, rounded to nearest (ties to even);
 * beyond 65504 it saturates to infinity (the compact map scales counts to stay far below). */
inline uint16_t toHalf(float f)
{
	uint32_t x;
	std::memcpy(&x, &f, 4);
	const uint16_t sign = uint16_t((x >> 16) & 0x8000u);
	x &= 0x7fffffffu;
	if (x >= 0x7f800000u) return uint16_t(sign | 0x7c00u | (x > 0x7f800000u ? 0x200u : 0u));  // inf, NaN
	if (x >= 0x477ff000u) return uint16_t(sign | 0x7c00u);  // rounds beyond 65504
	if (x < 0x38800000u)  // below the smallest normal half (2^-14): a subnormal or 0
	{
		if (x < 0x33000000u) return sign;  // below half the smallest subnormal (2^-25)
		const uint32_t e = x >> 23, m = (x & 0x7fffffu) | 0x800000u;
		const uint32_t shift = 126 - e;  // value m 2^(e-150) = (m >> shift) 2^-24
		const uint32_t q = m >> shift, rem = m & ((1u << shift) - 1), halfway = 1u << (shift - 1);
		const uint32_t r = q + (rem > halfway || (rem == halfway && (q & 1u)));
		return uint16_t(sign | r);
	}
	const uint32_t q = (x - 0x38000000u) >> 13, rem = x & 0x1fffu;  // rebias 127 -> 15
	const uint32_t r = q + (rem > 0x1000u || (rem == 0x1000u && (q & 1u)));
	return uint16_t(sign | r);
}

/** The float a binary16 stands for (exact). */
inline float fromHalf(uint16_t h)
{
	const uint32_t sign = uint32_t(h & 0x8000u) << 16, e = (h >> 10) & 0x1fu, m = h & 0x3ffu;
	uint32_t x;
	if (e == 0x1f)
		x = sign | 0x7f800000u | (m << 13);
	else if (e != 0)
		x = sign | ((e + 112u) << 23) | (m << 13);
	else if (m == 0)
		x = sign;
	else  // subnormal: m * 2^-24
	{
		float f = float(m) * (1.0f / 16777216.0f);
		std::memcpy(&x, &f, 4);
		x |= sign;
	}
	float f;
	std::memcpy(&f, &x, 4);
	return f;
}

}  // namespace gridvector
