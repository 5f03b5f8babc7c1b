// The .gvmap format (CGridVectorMap serialization): version 2 stores the vectors as a CompactMap,
// version 1 (the config by name, cells as floats) and version 0 (the config by position, when its
// key count matches) still load; corrupt input is an error.
#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/maps/CGridVectorMap.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/filesystem.h>

#include <cmath>
#include <fstream>
#include <iterator>

#include "test_scans.h"

using mrpt::maps::CGridVectorMap;
using mrpt::math::TPose2D;
using Archive = mrpt::serialization::CArchive;

namespace
{
CGridVectorMap mapOfRoom()
{
	const auto room = gvtest::room(-3, -2, 5, 3);
	CGridVectorMap m;
	for (int k = 0; k < 3; ++k)
	{
		const TPose2D p(0.5 * k, 0.2, 0.4 + 0.8 * k);
		m.insertObservation(gvtest::castScan(p, room, {}, 361, M_PI), mrpt::poses::CPose3D(mrpt::poses::CPose2D(p)));
	}
	return m;
}

std::string bytesOf(mrpt::io::CMemoryStream& buf)
{
	const auto* p = static_cast<const char*>(buf.getRawBufferData());
	return std::string(p, p + buf.getTotalBytesCount());
}

// MRPT's object framing (CArchive::WriteObject): class-name length | 0x80, the name, the version,
// the payload, the end flag 0x88. The test checks it against a real write first.
void beginObject(Archive& a, uint8_t version)
{
	const std::string cls = CGridVectorMap::GetRuntimeClassIdStatic().className;
	a << int8_t(int8_t(cls.size()) | int8_t(0x80));
	a.WriteBuffer(cls.data(), cls.size());
	a << int8_t(version);
}
void endObject(Archive& a) { a << uint8_t(0x88); }

void writeKey(Archive& a, const std::string& name, double value)
{
	a << uint8_t(name.size());
	a.WriteBuffer(name.data(), name.size());
	a << value;
}

// Everything after the config record: likelihood options, one vector of 2 columns, map params.
void writeRest(Archive& a, int rows)
{
	a << 0.07 << 0.3 << 0.05 << int32_t(2);
	a << uint64_t(5) << uint64_t(1);
	a << 0.0 << 0.0 << 0.2 << 0.0 << int32_t(2) << int64_t(4) << 1.5 << uint64_t(9) << uint8_t(0) << uint32_t(1);
	std::vector<gridvector::GridCell> cells(size_t(rows) * 2);
	cells[0].n_occupy = 3;
	a.WriteBuffer(cells.data(), cells.size() * sizeof(gridvector::GridCell));
	a << mrpt::maps::TMapGenericParams();
}

// A version-1 stream whose config record holds exactly these keys, then writeRest(3 rows).
void writeVersion1(mrpt::io::CMemoryStream& buf, const std::vector<std::pair<std::string, double>>& keys)
{
	auto a = mrpt::serialization::archiveFrom(buf);
	beginObject(a, 1);
	a << uint32_t(keys.size());
	for (const auto& [name, value] : keys) writeKey(a, name, value);
	writeRest(a, 3);
	endObject(a);
}

CGridVectorMap load(mrpt::io::CMemoryStream& buf)
{
	buf.Seek(0);
	auto a = mrpt::serialization::archiveFrom(buf);
	CGridVectorMap m;
	a >> m;
	return m;
}

std::string loadError(mrpt::io::CMemoryStream& buf)
{
	try
	{
		load(buf);
	}
	catch (const std::exception& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

TEST(GvmapFormat, WritesVersion2WithTheConfigByName)
{
	const CGridVectorMap m = mapOfRoom();
	EXPECT_EQ(m.GetRuntimeClass()->className, std::string(CGridVectorMap::GetRuntimeClassIdStatic().className));
	mrpt::io::CMemoryStream real, head;
	auto a = mrpt::serialization::archiveFrom(real);
	a << m;
	auto h = mrpt::serialization::archiveFrom(head);
	beginObject(h, 2);
	const std::string bytes = bytesOf(real), framing = bytesOf(head);
	EXPECT_EQ(bytes.substr(0, framing.size()), framing);  // the framing the tests below write
	EXPECT_EQ(uint8_t(bytes.back()), 0x88);
	for (const auto& [name, value] : m.config().namedValues()) EXPECT_NE(bytes.find(name), std::string::npos) << name;
}

TEST(GvmapFormat, RoundTripKeepsConfigVectorsAndCounts)
{
	CGridVectorMap a;
	auto cfg = a.config();
	cfg.grid.halfWidth = 2;  // changes the cell layout the reader must use
	cfg.map.mergeOnInsert = false;
	cfg.mstep.sequentialWindow = 7;
	a.setConfig(cfg);
	for (int k = 0; k < 3; ++k)
	{
		const TPose2D p(0.3 * k, -0.1, 0.2 * k);
		a.insertObservation(gvtest::castScan(p, gvtest::room(-3, -2, 5, 3), {}, 361, M_PI),
							mrpt::poses::CPose3D(mrpt::poses::CPose2D(p)));
	}
	ASSERT_FALSE(a.isEmpty());
	cfg.grid.halfWidth = 1;
	EXPECT_THROW(a.setConfig(cfg), std::invalid_argument);  // the vectors' grids are laid out with it
	mrpt::io::CMemoryStream buf;
	auto arch = mrpt::serialization::archiveFrom(buf);
	arch << a;
	const CGridVectorMap b = load(buf);
	EXPECT_EQ(b.config().namedValues(), a.config().namedValues());
	ASSERT_EQ(b.vectors().size(), a.vectors().size());
	EXPECT_EQ(b.insertedScans(), a.insertedScans());
	for (size_t i = 0; i < a.vectors().size(); ++i)
	{
		ASSERT_EQ(b.vectors()[i].rows(), 5);
		ASSERT_EQ(b.vectors()[i].cells().size(), a.vectors()[i].cells().size());
		for (size_t k = 0; k < a.vectors()[i].cells().size(); ++k)
			EXPECT_NEAR(b.vectors()[i].cells()[k].n_visit, a.vectors()[i].cells()[k].n_visit,
						5e-4 * a.vectors()[i].cells()[k].n_visit);  // half floats (CompactMap)
	}
}

TEST(GvmapFormat, KeysMissingFromTheFileTakeTheirDefaults)
{
	mrpt::io::CMemoryStream buf;
	writeVersion1(buf, {{"grid.resolution", 0.2}, {"map.merge_on_insert", 0}});  // grid.half_width missing: 1, 3 rows
	const CGridVectorMap m = load(buf);
	const gridvector::GridVectorConfig defaults;
	EXPECT_DOUBLE_EQ(m.config().grid.resolution, 0.2);
	EXPECT_FALSE(m.config().map.mergeOnInsert);
	EXPECT_EQ(m.config().grid.halfWidth, defaults.grid.halfWidth);
	EXPECT_DOUBLE_EQ(m.config().extraction.minLength, defaults.extraction.minLength);
	EXPECT_EQ(m.config().mstep.maxIterations, defaults.mstep.maxIterations);
	ASSERT_EQ(m.vectors().size(), 1u);
	EXPECT_EQ(m.vectors()[0].id, 9u);
	EXPECT_FLOAT_EQ(m.vectors()[0].cells()[0].n_occupy, 3.f);
	EXPECT_EQ(m.insertedScans(), 5u);
	EXPECT_DOUBLE_EQ(m.likelihoodOptions.sigma, 0.07);
}

TEST(GvmapFormat, RetiredKeysOfEarlierVersionsLoadAndAreIgnored)
{
	mrpt::io::CMemoryStream buf;
	writeVersion1(buf, {{"grid.resolution", 0.2}, {"estep.hysteresis", 0.1}, {"map.wipe_vectorless_beams", 1}});
	const CGridVectorMap m = load(buf);
	EXPECT_DOUBLE_EQ(m.config().grid.resolution, 0.2);
	for (const auto& [name, value] : m.config().namedValues())
		EXPECT_TRUE(name != "estep.hysteresis" && name != "map.wipe_vectorless_beams") << name;
}

TEST(GvmapFormat, UnknownKeyIsAnErrorNamingTheKey)
{
	mrpt::io::CMemoryStream buf;
	writeVersion1(buf, {{"grid.resolution", 0.1}, {"grid.future_option", 1}});
	const std::string err = loadError(buf);
	EXPECT_NE(err.find("stored config key 'grid.future_option' is unknown to this version"), std::string::npos) << err;
}

TEST(GvmapFormat, StoredValuesAreValidated)
{
	for (const auto& [key, value] : std::vector<std::pair<std::string, double>>{
			 {"grid.half_width", 1.5}, {"map.merge_on_insert", 2}, {"grid.resolution", -1}})
	{
		mrpt::io::CMemoryStream buf;
		writeVersion1(buf, {{key, value}});
		const std::string err = loadError(buf);
		EXPECT_NE(err.find("stored config"), std::string::npos) << key << ": " << err;
	}
}

// Version 0 (frozen): key count + every value in visit() order, by position.
TEST(GvmapFormat, Version0LoadsWhenItsKeyCountMatches)
{
	auto writeV0 = [](mrpt::io::CMemoryStream& buf, uint32_t extraKeys) {
		auto a = mrpt::serialization::archiveFrom(buf);
		gridvector::GridVectorConfig c;
		c.extraction.minLength = 0.42;
		c.map.mergeOnInsert = false;  // not the default
		beginObject(a, 0);
		a << uint32_t(c.namedValues().size() + extraKeys);
		c.visitGroups([&](const char*, auto& g) {
			g.visit([&](const char*, auto& field, const char*, const gridvector::Range&) { a << field; });
		});
		writeRest(a, 3);
		endObject(a);
	};
	mrpt::io::CMemoryStream same, other;
	writeV0(same, 0);
	const CGridVectorMap m = load(same);
	EXPECT_DOUBLE_EQ(m.config().extraction.minLength, 0.42);
	EXPECT_FALSE(m.config().map.mergeOnInsert);
	ASSERT_EQ(m.vectors().size(), 1u);
	EXPECT_EQ(m.vectors()[0].scanIndex, 4);

	writeV0(other, 1);
	EXPECT_NE(loadError(other).find("stored config has"), std::string::npos);
}

TEST(GvmapFormat, TruncatedOrCorruptStreamsAreErrorsNotCrashes)
{
	const CGridVectorMap m = mapOfRoom();
	mrpt::io::CMemoryStream real;
	auto a = mrpt::serialization::archiveFrom(real);
	a << m;
	const std::string bytes = bytesOf(real);
	ASSERT_GT(bytes.size(), 1000u);
	// every prefix length in 1/64 steps fails with an exception
	for (size_t k = 0; k < 64; ++k)
	{
		mrpt::io::CMemoryStream cut;
		cut.Write(bytes.data(), bytes.size() * k / 64);
		EXPECT_THROW(load(cut), std::exception) << "cut at " << bytes.size() * k / 64;
	}
	// overwritten bytes in the header, config and first vector records: an error or a valid map, never a crash
	for (size_t pos = 0; pos < std::min<size_t>(bytes.size(), 2000); pos += 7)
		for (const char garbage : {'\xff', '\x7f', '\x00'})
		{
			std::string bad = bytes;
			bad[pos] = garbage;
			mrpt::io::CMemoryStream s;
			s.Write(bad.data(), bad.size());
			try
			{
				load(s);
			}
			catch (const std::exception&)
			{}
		}
	// a vector count and a column count far beyond the data fail without allocating them
	mrpt::io::CMemoryStream huge;
	auto h = mrpt::serialization::archiveFrom(huge);
	beginObject(h, 1);
	h << uint32_t(0) << 0.05 << 0.3 << 0.05 << int32_t(2) << uint64_t(1) << (uint64_t(1) << 40);
	h << 0.0 << 0.0 << 0.2 << 0.0 << int32_t(9'000'000) << int64_t(0) << 0.0 << uint64_t(0) << uint8_t(0)
	  << uint32_t(1);
	EXPECT_THROW(load(huge), std::exception);
}

TEST(GvmapFormat, TruncatedGzipFileIsAnError)
{
	const std::string path = mrpt::system::getTempFileName() + ".gvmap";
	mapOfRoom().saveToFile(path);
	std::string data;
	{
		std::ifstream in(path, std::ios::binary);
		data.assign(std::istreambuf_iterator<char>(in), {});
	}
	std::ofstream(path, std::ios::binary | std::ios::trunc).write(data.data(), std::streamsize(data.size() / 2));
	mrpt::io::CFileGZInputStream f;
	ASSERT_TRUE(f.open(path));
	auto a = mrpt::serialization::archiveFrom(f);
	CGridVectorMap m;
	EXPECT_THROW(a >> m, std::exception);
	mrpt::system::deleteFile(path);
}

TEST(GvmapFormat, LoadFromFileReadsWhatSaveToFileWrote)
{
	const std::string path = mrpt::system::getTempFileName() + ".gvmap";
	CGridVectorMap saved = mapOfRoom();
	saved.likelihoodOptions.sigma = 0.08;
	saved.saveToFile(path);
	CGridVectorMap loaded;
	loaded.loadFromFile(path);
	EXPECT_EQ(loaded.insertedScans(), saved.insertedScans());
	EXPECT_EQ(loaded.likelihoodOptions.sigma, 0.08);
	EXPECT_EQ(loaded.config().namedValues(), saved.config().namedValues());
	ASSERT_EQ(loaded.vectors().size(), saved.vectors().size());
	for (size_t i = 0; i < saved.vectors().size(); ++i)
	{
		EXPECT_NEAR(loaded.vectors()[i].start().x, saved.vectors()[i].start().x, 5e-4);  // the 1 mm lattice
		EXPECT_NEAR(loaded.vectors()[i].end().y, saved.vectors()[i].end().y, 5e-4);
		EXPECT_EQ(loaded.vectors()[i].cells().size(), saved.vectors()[i].cells().size());
	}
	mrpt::system::deleteFile(path);
}

TEST(GvmapFormat, LoadFromFileFailureLeavesTheMapAsItWas)
{
	CGridVectorMap m = mapOfRoom();
	const size_t before = m.vectors().size();
	try
	{
		m.loadFromFile("/no/such/map.gvmap");
		FAIL() << "a missing file loaded";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("/no/such/map.gvmap"), std::string::npos) << e.what();
	}
	const std::string path = mrpt::system::getTempFileName() + ".gvmap";
	std::ofstream(path) << "not a map";
	EXPECT_THROW(m.loadFromFile(path), std::runtime_error);
	EXPECT_EQ(m.vectors().size(), before);
	mrpt::system::deleteFile(path);
}

// issue 22: the stored likelihood options and cells are checked as the .ini path checks them
TEST(GvmapFormat, StoredLikelihoodOptionsAndCellsAreValidated)
{
	const auto withRest = [](double sigma, int32_t decimation, float nOccupy) {
		mrpt::io::CMemoryStream buf;
		auto a = mrpt::serialization::archiveFrom(buf);
		beginObject(a, 1);
		a << uint32_t(0);
		a << sigma << 0.3 << 0.05 << decimation;
		a << uint64_t(5) << uint64_t(1);
		a << 0.0 << 0.0 << 0.2 << 0.0 << int32_t(2) << int64_t(4) << 1.5 << uint64_t(9) << uint8_t(0) << uint32_t(1);
		std::vector<gridvector::GridCell> cells(3 * 2);
		cells[1].n_occupy = nOccupy;
		a.WriteBuffer(cells.data(), cells.size() * sizeof(gridvector::GridCell));
		a << mrpt::maps::TMapGenericParams();
		endObject(a);
		return loadError(buf);
	};
	EXPECT_EQ(withRest(0.07, 2, 1), "");
	for (double sigma : {std::nan(""), 0.0, -1.0})
		EXPECT_NE(withRest(sigma, 2, 1).find("stored likelihood option sigma"), std::string::npos) << sigma;
	EXPECT_NE(withRest(0.07, 0, 1).find("stored likelihood option decimation = 0"), std::string::npos);
	EXPECT_NE(
		withRest(0.07, 2, std::nanf("")).find("corrupt vector record 0 (a cell with a negative or non-finite count)"),
		std::string::npos);
	EXPECT_NE(withRest(0.07, 2, -1).find("corrupt vector record 0"), std::string::npos);
}

TEST(GvmapFormat, LoadingChecksTheGzipCrc)
{
	const std::string path = mrpt::system::getTempFileName() + ".gvmap";
	mapOfRoom().saveToFile(path);
	std::string data;
	{
		std::ifstream in(path, std::ios::binary);
		data.assign(std::istreambuf_iterator<char>(in), {});
	}
	const auto loadError = [&](const std::string& bytes) {
		std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), std::streamsize(bytes.size()));
		try
		{
			CGridVectorMap m;
			m.loadFromFile(path);
		}
		catch (const std::exception& e)
		{
			return std::string(e.what());
		}
		return std::string();
	};
	EXPECT_EQ(loadError(data), "");
	EXPECT_EQ(loadError(data.substr(0, data.size() - 8)),
			  path + ": truncated or corrupt gzip data (CRC/length trailer mismatch)");  // the trailer cut
	std::string crc = data;
	crc[crc.size() - 6] ^= 0x40;  // the stored CRC-32 altered: the data no longer match it
	EXPECT_EQ(loadError(crc), path + ": truncated or corrupt gzip data (CRC/length trailer mismatch)");
	mrpt::system::deleteFile(path);
}
