// Table 1: memory accounting of the grid vector map.
#include "map/MemoryAccounting.h"
#include "io/JsonFile.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <sstream>

using namespace gridvector;

TEST(MemoryAccounting, ReproducesTable1Fig7)
{
	// Fig. 7: a region of 678.56 m^2 (here 38 x 17.8568 m) and 194.73 m of vectors.
	const double w = 38.0, h = 678.56 / 38.0, rest = 194.73 - 4 * w - 2 * h;
	std::vector<GridVector> vs{
		GridVector({0, 0}, {w, 0}, GridOptions{}),     GridVector({w, 0}, {w, h}, GridOptions{}),
		GridVector({w, h}, {0, h}, GridOptions{}),     GridVector({0, h}, {0, 0}, GridOptions{}),
		GridVector({0, 5}, {w, 5}, GridOptions{}),     GridVector({w, 10}, {0, 10}, GridOptions{}),
		GridVector({0, 12}, {rest, 12}, GridOptions{})};
	const MemoryReport r = MemoryAccounting::account(vs);
	EXPECT_NEAR(r.spaceSize, 678.56, 1e-6);
	EXPECT_NEAR(r.vectorLength, 194.73, 1e-6);
	EXPECT_EQ(r.n_g, 67856u);
	EXPECT_EQ(r.n_v, 1947u);
	EXPECT_NEAR(r.ratio, 34.85, 0.005);
	// the honest count includes the grid's width (3 rows by default)
	EXPECT_EQ(r.cells, 3 * r.columns);
	EXPECT_GE(r.columns, r.n_v);
	EXPECT_NEAR(r.ratioCells, double(r.n_g) / r.cells, 1e-12);
	EXPECT_EQ(r.bytesGrid, r.n_g * r.bytesPerGridCell);
	EXPECT_GE(r.bytesWorkingForm, r.cells * sizeof(GridCell) + vs.size() * sizeof(GridVector));
	// the map as held: the compact buffer, prior cells at 2 bytes, 2 bits of kind per cell
	EXPECT_LT(r.bytesGridVector * 5, r.bytesWorkingForm);
	EXPECT_GE(r.bytesGridVector, r.cells * 2);
	EXPECT_NEAR(r.ratioBytesWorkingForm, double(r.bytesGrid) / r.bytesWorkingForm, 1e-12);
}

TEST(MemoryAccounting, JsonHasEveryFigure)
{
	const std::vector<GridVector> vs{GridVector({0, 0}, {10, 0}, GridOptions{}),
									 GridVector({0, 5}, {10, 5}, GridOptions{})};
	const MemoryReport r = MemoryAccounting::account(vs);
	EXPECT_EQ(r.n_g, 5000u);
	EXPECT_EQ(r.n_v, 200u);
	const nlohmann::ordered_json j = MemoryAccounting::toJson(r);
	EXPECT_DOUBLE_EQ(j["space_size_m2"].get<double>(), 50);
	EXPECT_EQ(j["n_g"], 5000);
	EXPECT_EQ(j["n_v"], 200);
	EXPECT_DOUBLE_EQ(j["ratio_ng_nv"].get<double>(), 25);
	EXPECT_EQ(j["grid_vector_cells"], 600);
	for (const char* k : {"bytes_occupancy_grid", "bytes_grid_vector_map", "bytes_working_form", "bytes_gvmap_file"})
		EXPECT_TRUE(j.contains(k)) << k;
	EXPECT_EQ(j.begin().key(), "resolution_m") << "the keys in the order of MemoryReport's fields";
	const std::string path = ::testing::TempDir() + "/memory_accounting_test.json";
	MemoryAccounting::writeJson(r, path);
	std::ifstream in(path);
	std::stringstream ss;
	ss << in.rdbuf();
	EXPECT_EQ(ss.str(), io::jsonText(j));
	std::remove(path.c_str());
	EXPECT_NE(MemoryAccounting::summary(r).find("n_g/n_v = 25.00"), std::string::npos);
	EXPECT_EQ(MemoryAccounting::account({}).n_g, 0u);
}
