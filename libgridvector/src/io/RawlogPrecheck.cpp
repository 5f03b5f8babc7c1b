#include "io/RawlogPrecheck.h"
#include "io/InputLimits.h"
#include "io/TextParsing.h"

#include <mrpt/rtti/CObject.h>

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

namespace gridvector::io
{
namespace
{
/** MRPT's end-of-object byte (CArchive.cpp: SERIALIZATION_END_FLAG). */
constexpr uint8_t kEndFlag = 0x88;
/** Most particles a Thrun motion model may ask MRPT to draw for one action (MRPT's default: 300). */
constexpr uint32_t kMaxParticles = 100000;
/** Smallest serialised object: a one-letter class name, version and end flag. */
constexpr size_t kMinObjectBytes = 4;

/** Signals an object of a class this walker does not know (the entry goes to MRPT unchecked). */
struct UnknownClass
{};

class Walker
{
   public:
	Walker(const unsigned char* p, size_t n) : p_(p), n_(n) {}

	/** One object; `inContainer`: a null object is an error (the reader dereferences the children). */
	void object(bool inContainer)
	{
		const std::string name = header();
		if (name == "nullptr")
		{
			if (inContainer) fail("a null object inside a sensory frame or action collection");
			return endFlag(name);
		}
		requireCreatable(name);
		const size_t ns = name.rfind("::");  // MRPT 2 writes "mrpt::obs::CSensoryFrame", MRPT 1 "CSensoryFrame"
		payload(ns == std::string::npos ? name : name.substr(ns + 2), version_);
		endFlag(name);
	}

   private:
	[[noreturn]] void fail(const std::string& what) const { throw std::runtime_error(what); }

	void need(size_t k, const char*) const
	{
		if (k > n_ - pos_) throw TruncatedEntry();
	}
	template <class T>
	T get(const char* what)
	{
		need(sizeof(T), what);
		T v;
		std::memcpy(&v, p_ + pos_, sizeof(T));  // MRPT writes little-endian; so does every host gridvector runs on
		pos_ += sizeof(T);
		return v;
	}
	void skip(size_t k, const char* what)
	{
		need(k, what);
		pos_ += k;
	}
	/** A count of items of at least `itemBytes` each: at most `limit`, and they must fit the bytes left. */
	uint32_t count(const char* what, size_t limit, size_t itemBytes)
	{
		const uint32_t c = get<uint32_t>(what);
		if (c > limit)
			fail(std::string(what) + " is " + std::to_string(c) + " (at most " + std::to_string(limit) + ")");
		if (size_t(c) * itemBytes > n_ - pos_)
			fail(std::string(what) + " is " + std::to_string(c) + ": needs " + std::to_string(size_t(c) * itemBytes) +
				 " bytes, " + std::to_string(n_ - pos_) + " are left in the file");
		return c;
	}

	/** MRPT prints to stderr, then fails, on a class it cannot create (an abstract one): say it here. */
	void requireCreatable(const std::string& name) const
	{
		const mrpt::rtti::TRuntimeClassId* id = mrpt::rtti::findRegisteredClass(name);
		if (!id) fail("an object of class '" + printableToken(name) + "', which is not registered");
		if (!id->ptrCreateObject) fail("an object of abstract class '" + name + "'");
	}

	std::string header()
	{
		const uint8_t b = get<uint8_t>("an object header");
		if (!(b & 0x80)) throw UnknownClass{};  // pre-0.5.5 framing: MRPT's to read
		const size_t len = b & 0x7F;
		if (len == 0 || len > 120) fail("an object's class name has " + std::to_string(len) + " characters");
		need(len, "a class name");
		std::string name(reinterpret_cast<const char*>(p_ + pos_), len);
		pos_ += len;
		if (name != "nullptr") version_ = get<uint8_t>("an object version");
		return name;
	}
	void endFlag(const std::string& name)
	{
		if (get<uint8_t>("an end-of-object flag") != kEndFlag)
			fail("the " + name + " object does not end where its fields say (end flag missing)");
	}
	void string(const char* what) { skip(count(what, kMaxRawlogString, 1), what); }

	void payload(const std::string& name, uint8_t v)
	{
		if (name == "CSensoryFrame")
			sensoryFrame(v);
		else if (name == "CActionCollection")
			children(v == 0, "the action count");
		else if (name == "CObservation2DRangeScan")
			scan2D(v);
		else if (name == "CObservationOdometry")
			odometry(v);
		else if (name == "CActionRobotMovement2D")
			movement2D(v);
		else if (name == "CPose2D")
			skip(v == 0 ? 12 : v == 1 ? 24 : unknownVersion(name, v), "a CPose2D");
		else if (name == "CPose3D")
			skip(v == 2 ? 56 : v == 3 ? 96 : size_t(throwUnknown()), "a CPose3D");
		else if (name == "CPosePDFGaussian")
			poseGaussian(v);
		else if (name == "CPosePDFGaussianInf")
			skip(v == 0 ? 72 : unknownVersion(name, v), "a CPosePDFGaussianInf");
		else if (name == "CMatrixF")
			matrixF(v);
		else
			throw UnknownClass{};
	}
	[[noreturn]] size_t unknownVersion(const std::string& name, uint8_t v) const
	{
		fail("a " + name + " object of serialisation version " + std::to_string(v) + " (unknown)");
	}
	[[noreturn]] static int throwUnknown() { throw UnknownClass{}; }

	void children(bool knownVersion, const char* what)
	{
		if (!knownVersion) fail(std::string("a container of unknown serialisation version for ") + what);
		const uint32_t n = count(what, kMaxRawlogChildren, kMinObjectBytes);
		for (uint32_t i = 0; i < n; ++i) object(true);
	}
	void sensoryFrame(uint8_t v)
	{
		if (v > 2) unknownVersion("CSensoryFrame", v);
		if (v < 2) skip(4, "a sensory frame's ID");
		if (v == 0) skip(8, "a sensory frame's timestamp");
		children(true, "the sensory frame's observation count");
	}
	void matrixF(uint8_t v)
	{
		if (v != 0) unknownVersion("CMatrixF", v);
		const uint32_t rows = get<uint32_t>("a matrix's rows"), cols = get<uint32_t>("a matrix's columns");
		if (rows > 1000 || cols > 1000)
			fail("a " + std::to_string(rows) + " x " + std::to_string(cols) + " matrix (at most 1000 x 1000)");
		skip(size_t(rows) * cols * 4, "a matrix's values");
	}
	void scan2D(uint8_t v)
	{
		if (v > 7) unknownVersion("CObservation2DRangeScan", v);
		skip(4 + 1 + 4, "a scan's aperture, direction and max range");
		object(false);  // sensorPose, a CPose3D
		if (v < 6) object(false);  // covSensorPose, a CMatrixF
		const uint32_t n = count("the scan's beam count", kMaxBeams, v >= 1 ? 5 : 4);
		skip(size_t(n) * (v >= 1 ? 5 : 4), "the scan's ranges and validity flags");
		if (v <= 3)
		{
			if (v >= 2) skip(4, "a scan's stdError");
			if (v >= 3) skip(8, "a scan's timestamp");
			return;
		}
		skip(4 + 8 + 4, "a scan's stdError, timestamp and beam aperture");
		if (v >= 5)
		{
			string("the scan's sensor label length");
			skip(8, "a scan's deltaPitch");  // a double
		}
		if (v >= 7 && get<uint8_t>("a scan's intensity flag")) skip(size_t(n) * 4, "the scan's intensities");
	}
	void odometry(uint8_t v)
	{
		if (v > 2) unknownVersion("CObservationOdometry", v);
		object(false);  // the CPose2D
		string("the odometry's sensor label length");
		skip(8, "an odometry timestamp");
		if (v == 0) return;
		const bool encoders = get<uint8_t>("an encoder flag");
		if (encoders || v < 2) skip(8, "encoder ticks");
		const bool velocities = get<uint8_t>("a velocity flag");
		if (v < 2)
			skip(8, "velocities");
		else if (velocities)
			skip(24, "velocities");
	}
	void movement2D(uint8_t v)
	{
		if (v < 4) return oldMovement2D(v);
		if (v > 7) unknownVersion("CActionRobotMovement2D", v);
		const int32_t method = get<int32_t>("an estimation method");
		if (method != 0 && method != 1)
			fail("a robot movement's estimation method is " + std::to_string(method) + " (0 or 1)");
		if (method == 0)  // emOdometry: the increment and the motion model MRPT re-draws the PDF from
		{
			object(false);
			const int32_t model = get<int32_t>("a motion model");
			if (model != 0 && model != 1)
				fail("a robot movement's motion model is " + std::to_string(model) + " (0 or 1)");
			skip(6 * 4, "a Gaussian motion model");
			const uint32_t particles = get<uint32_t>("a particle count");
			if (model == 1 && (particles == 0 || particles > kMaxParticles))
				fail("a robot movement's Thrun model draws " + std::to_string(particles) + " particles (1.." +
					 std::to_string(kMaxParticles) + ")");
			skip(4 * 4 + (v >= 5 ? 8 : 0), "a Thrun motion model");
		}
		else
			object(false);  // the pose change PDF
		const bool velocities = get<uint8_t>("a velocity flag");
		if (v >= 7)
		{
			if (velocities) skip(24, "velocities");
		}
		else
			skip(8, "velocities");
		const bool encoders = get<uint8_t>("an encoder flag");
		if (v < 7 || encoders) skip(8, "encoder ticks");
		if (v >= 6) skip(8, "a movement's timestamp");
	}
	void method(int32_t m) const
	{
		if (m != 0 && m != 1) fail("a robot movement's estimation method is " + std::to_string(m) + " (0 or 1)");
	}
	/** Versions 0-3 (MRPT < 1.0): MRPT dereferences the pose change of versions 0-1 and re-draws 2-3's. */
	void oldMovement2D(uint8_t v)
	{
		if (v <= 1)
		{
			object(true);  // the pose change PDF: must not be null
			method(get<int32_t>("an estimation method"));
			if (v == 1) skip(1 + 8 + 1 + 8, "velocities and encoders");
			return;
		}
		const int32_t m = get<int32_t>("an estimation method");
		method(m);
		if (m == 0)
		{
			object(false);  // the odometry increment
			if (v == 2)
				skip(44, "an old motion model");
			else
			{
				const int32_t model = get<int32_t>("a motion model");
				if (model != 0 && model != 1)
					fail("a robot movement's motion model is " + std::to_string(model) + " (0 or 1)");
				skip(3 * 4 + 2 * 8, "a Gaussian motion model");
				const uint32_t particles = get<uint32_t>("a particle count");
				if (model == 1 && (particles == 0 || particles > kMaxParticles))
					fail("a robot movement's Thrun model draws " + std::to_string(particles) + " particles");
				skip(4 * 4, "a Thrun motion model");
			}
		}
		else
			object(false);
		skip(1 + 8 + 1 + 8, "velocities and encoders");
	}
	void poseGaussian(uint8_t v)
	{
		if (v > 2) unknownVersion("CPosePDFGaussian", v);
		object(false);  // the mean, a CPose2D
		if (v == 0)
			object(false);  // a CMatrixF
		else
			skip(v == 2 ? 48 : 24, "a covariance");
	}

	const unsigned char* p_;
	size_t n_;
	size_t pos_ = 0;
	uint8_t version_ = 0;
};
}  // namespace

EntryCheck precheckRawlogEntry(const unsigned char* bytes, size_t size)
{
	try
	{
		Walker(bytes, size).object(false);
		return EntryCheck::Checked;
	}
	catch (const UnknownClass&)
	{
		return EntryCheck::Unchecked;
	}
}

}  // namespace gridvector::io
