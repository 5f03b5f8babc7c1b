// Exports: ROS map_server PGM/YAML, PNG, SVG, vectors.txt, MRPT .3Dscene; all atomic.
#include "map/MapExport.h"
#include "map/OccupancyConversion.h"

#include <gtest/gtest.h>
#include <mrpt/img/CImage.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfLines.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace gridvector;
namespace fs = std::filesystem;

namespace
{
std::vector<GridVector> sampleMap()
{
	GridVector wall({0, 0}, {4, 0}, GridOptions{}), door({4, 0}, {4, 1}, GridOptions{}),
		person({1, 2}, {2, 2}, GridOptions{});
	for (int c = 0; c < wall.cols(); ++c) wall.cell(1, c) = wall.cell(0, c) = GridCell{0, 0, 0, 19.5f, 20.f};
	for (int c = 0; c < wall.cols(); ++c) wall.cell(2, c) = GridCell{0, 0, 0, 0.5f, 20.f};
	for (auto& c : person.cells()) c.n_occupy = 0.5f, c.n_visit = 10.f;
	wall.state = VectorState::Static;
	door.state = VectorState::Dynamic;
	return {wall, door, person};
}

std::string slurp(const std::string& p)
{
	std::ifstream f(p, std::ios::binary);
	std::stringstream s;
	s << f.rdbuf();
	return s.str();
}

struct TempDir
{
	fs::path path;
	TempDir() : path(fs::temp_directory_path() / ("gv_export_" + std::to_string(::getpid())))
	{
		fs::create_directories(path);
	}
	~TempDir() { fs::remove_all(path); }
	std::string operator/(const std::string& f) const { return (path / f).string(); }
	size_t files() const { return size_t(std::distance(fs::directory_iterator(path), fs::directory_iterator())); }
};
}  // namespace

TEST(MapExport, RosMapServerPgmAndYaml)
{
	const auto vs = sampleMap();
	OccupancyConversionOptions o;
	o.margin = 0.5;
	const auto grid = OccupancyConversion::toOccupancyGrid(vs, o);
	TempDir d;
	MapExport::writeRosMap(grid, d / "occ.pgm", d / "occ.yaml");
	const std::string pgm = slurp(d / "occ.pgm");
	std::istringstream in(pgm);
	std::string magic, comment;
	unsigned w, h, maxv;
	in >> magic;
	in.ignore(1);
	std::getline(in, comment);
	in >> w >> h >> maxv;
	in.ignore(1);
	EXPECT_EQ(magic, "P5");
	EXPECT_EQ(comment[0], '#');
	EXPECT_EQ(w, grid.getSizeX());
	EXPECT_EQ(h, grid.getSizeY());
	EXPECT_EQ(maxv, 255u);
	const size_t off = size_t(in.tellg());
	ASSERT_EQ(pgm.size() - off, size_t(w) * h);
	auto pixel = [&](double x, double y) {  // first row = top = largest y
		const int ix = grid.x2idx(x), iy = grid.y2idx(y);
		return (unsigned char)pgm[off + size_t(h - 1 - iy) * w + size_t(ix)];
	};
	EXPECT_LT(pixel(2.0, -0.05), 40);  // cell [-0.1, 0]: wall rows, p = 0.975
	EXPECT_GT(pixel(2.0, 0.15), 240);  // cell [0.1, 0.2]: the free row, p = 0.025
	EXPECT_EQ(pixel(2.0, 1.0), 128);  // unknown: 0.5
	const std::string yaml = slurp(d / "occ.yaml");
	for (const char* k : {"image: occ.pgm\n", "resolution: 0.1\n", "origin: [", "negate: 0\n",
						  "occupied_thresh: 0.65\n", "free_thresh: 0.196\n", "mode: trinary\n"})
		EXPECT_NE(yaml.find(k), std::string::npos) << k << "\n" << yaml;
	EXPECT_EQ(d.files(), 2u);  // no temporary left behind
}

TEST(MapExport, PngLoadsBack)
{
	const auto vs = sampleMap();
	const auto grid = OccupancyConversion::toOccupancyGrid(vs);
	TempDir d;
	MapExport::writePng(grid, d / "occ.png");
	mrpt::img::CImage img;
	ASSERT_TRUE(img.loadFromFile(d / "occ.png"));
	EXPECT_EQ(img.getWidth(), grid.getSizeX());
	EXPECT_EQ(img.getHeight(), grid.getSizeY());
	EXPECT_EQ(d.files(), 1u);
	EXPECT_THROW(MapExport::writePng(grid, "/nonexistent-dir/x.png"), std::runtime_error);
}

TEST(MapExport, SvgColoursAndWidths)
{
	const auto vs = sampleMap();
	EXPECT_EQ(MapExport::svgColour(vs[0]), "#0000ff");  // static: blue
	EXPECT_EQ(MapExport::svgColour(vs[1]), "#ff0000");  // dynamic: red
	EXPECT_EQ(MapExport::svgColour(vs[2]), "#f2000d");  // unknown, p_static 0.05: nearly red
	EXPECT_GT(MapExport::svgStrokeWidth(vs[0]), MapExport::svgStrokeWidth(vs[1]));  // confident static
	TempDir d;
	MapExport::writeSvg(vs, d / "v.svg");
	const std::string svg = slurp(d / "v.svg");
	EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
	size_t lines = 0;
	for (size_t p = svg.find("<line"); p != std::string::npos; p = svg.find("<line", p + 1)) ++lines;
	EXPECT_EQ(lines, 3u);
	EXPECT_NE(svg.find("stroke=\"#0000ff\""), std::string::npos);
	EXPECT_NE(svg.find("</svg>"), std::string::npos);
}

TEST(MapExport, VectorsTextRoundTrips)
{
	const auto vs = sampleMap();
	TempDir d;
	MapExport::writeVectorsText(vs, d / "v.txt");
	std::ifstream f(d / "v.txt");
	std::string header;
	std::getline(f, header);
	EXPECT_EQ(header[0], '#');
	for (const auto& v : vs)
	{
		double x1, y1, x2, y2, p;
		ASSERT_TRUE(bool(f >> x1 >> y1 >> x2 >> y2 >> p));
		EXPECT_NEAR(x1, v.start().x, 1e-6);
		EXPECT_NEAR(y2, v.end().y, 1e-6);
		EXPECT_NEAR(p, v.pStatic(), 1e-6);
	}
	EXPECT_THROW(MapExport::writeVectorsText(vs, "/nonexistent-dir/v.txt"), std::runtime_error);
}

TEST(MapExport, SceneLoadsInMrpt)
{
	const auto vs = sampleMap();
	const auto grid = OccupancyConversion::toOccupancyGrid(vs);
	TempDir d;
	MapExport::write3DScene(vs, grid, d / "m.3Dscene");
	mrpt::opengl::COpenGLScene scene;
	ASSERT_TRUE(scene.loadFromFile(d / "m.3Dscene"));
	size_t lines = 0;
	for (const auto& o : *scene.getViewport())
		if (auto l = std::dynamic_pointer_cast<mrpt::opengl::CSetOfLines>(o)) lines += l->size();
	EXPECT_EQ(lines, 3u);
	EXPECT_EQ(d.files(), 1u);
}
