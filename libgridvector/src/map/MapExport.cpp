#include "map/MapExport.h"
#include "io/ArchiveFile.h"
#include "io/AtomicFile.h"
#include "io/TextParsing.h"

#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/CSetOfObjects.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <unistd.h>

namespace gridvector
{
namespace
{
/** Writers that pick their format from the extension get a temporary name
 * ending like the target; renamed over it when done. */
std::string tempLike(const std::string& path)
{
	const std::filesystem::path p(path);
	return (p.parent_path() / ("." + p.stem().string() + ".tmp" + std::to_string(::getpid()) + p.extension().string()))
		.string();
}

void renameOver(const std::string& tmp, const std::string& path)
{
	std::error_code ec;
	std::filesystem::rename(tmp, path, ec);
	if (ec)
	{
		std::filesystem::remove(tmp, ec);
		throw std::runtime_error(path + ": cannot write (rename failed)");
	}
}

/** Writes `path` through `save` (an MRPT writer that picks its format from the extension)
 * under tempLike(path), renamed over it when done; `failure` names a failed save. */
template <class Save>
void saveVia(const std::string& path, const char* failure, Save&& save)
{
	const std::string tmp = tempLike(path);
	if (!save(tmp))
	{
		std::error_code ec;
		std::filesystem::remove(tmp, ec);
		throw std::runtime_error(path + ": cannot write (" + failure + ")");
	}
	renameOver(tmp, path);
}

std::string hex(int r, int g, int b)
{
	char buf[8];
	std::snprintf(buf, sizeof buf, "#%02x%02x%02x", r, g, b);
	return buf;
}

double confidence(const GridVector& v)
{
	const double p = v.pStatic();
	if (v.state == VectorState::Static) return p;
	if (v.state == VectorState::Dynamic) return 1 - p;
	return std::abs(2 * p - 1);
}

mrpt::img::TColor rgbOf(const GridVector& v)
{
	if (v.state == VectorState::Static) return {0, 0, 255};
	if (v.state == VectorState::Dynamic) return {255, 0, 0};
	const double t = std::clamp(v.pStatic(), 0.0, 1.0);
	return {uint8_t(std::lround(255 * (1 - t))), 0, uint8_t(std::lround(255 * t))};
}
}  // namespace

void MapExport::writePng(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& path)
{
	saveVia(path, "image encoder failed", [&](const std::string& tmp) { return grid.saveAsBitmapFile(tmp); });
}

// ROS map_server format: P5 image + YAML metadata.
void MapExport::writeRosMap(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& pgmPath,
							const std::string& yamlPath)
{
	const unsigned nx = grid.getSizeX(), ny = grid.getSizeY();
	io::AtomicFile pgm(pgmPath, io::AtomicFile::Mode::Binary);
	pgm.stream() << "P5\n# gridvector Eq. 6 occupancy, " << grid.getResolution() << " m/pixel\n"
				 << nx << " " << ny << "\n255\n";
	std::vector<unsigned char> row(nx);
	for (unsigned iy = ny; iy-- > 0;)  // top row first: largest y
	{
		for (unsigned ix = 0; ix < nx; ++ix)
		{
			const double occ = 1.0 - grid.getCell(int(ix), int(iy));  // MRPT stores p(free)
			row[ix] = (unsigned char)std::clamp(std::lround(255.0 * (1.0 - occ)), 0L, 255L);
		}
		pgm.stream().write(reinterpret_cast<const char*>(row.data()), std::streamsize(nx));
	}
	pgm.commit();
	io::writeFileAtomically(yamlPath, [&](std::ostream& y) {
		y.precision(9);
		y << "image: " << std::filesystem::path(pgmPath).filename().string() << "\n"
		  << "resolution: " << io::shortestText(grid.getResolution()) << "\n"
		  << "origin: [" << io::shortestText(grid.getXMin()) << ", " << io::shortestText(grid.getYMin()) << ", 0.0]\n"
		  << "negate: 0\n"
		  << "occupied_thresh: 0.65\n"
		  << "free_thresh: 0.196\n"
		  << "mode: trinary\n";
	});
}

void MapExport::writeVectorsText(const std::vector<GridVector>& vectors, const std::string& path)
{
	io::writeFileAtomically(path, [&](std::ostream& f) {
		f.precision(9);
		f << "# x1 y1 x2 y2 p_static   (" << vectors.size() << " grid vectors, world frame, metres)\n";
		for (const auto& v : vectors)
			f << v.start().x << ' ' << v.start().y << ' ' << v.end().x << ' ' << v.end().y << ' ' << v.pStatic()
			  << '\n';
	});
}

std::string MapExport::svgColour(const GridVector& v)
{
	const auto c = rgbOf(v);
	return hex(c.R, c.G, c.B);
}

double MapExport::svgStrokeWidth(const GridVector& v) { return 0.02 + 0.08 * confidence(v); }

void MapExport::writeSvg(const std::vector<GridVector>& vectors, const std::string& path)
{
	double x0 = 0, y0 = 0, x1 = 1, y1 = 1;
	if (!vectors.empty())
	{
		x0 = y0 = 1e300, x1 = y1 = -1e300;
		for (const auto& v : vectors)
			for (const auto& p : {v.start(), v.end()})
				x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
	}
	const double m = 0.5, w = x1 - x0 + 2 * m, h = y1 - y0 + 2 * m;
	io::writeFileAtomically(path, [&](std::ostream& f) {
		f.precision(6);
		f << std::fixed;
		f << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
		  << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << x0 - m << " " << -(y1 + m) << " " << w << " "
		  << h << "\" width=\"" << std::lround(std::min(4000.0, w * 40)) << "\" height=\""
		  << std::lround(std::min(4000.0, w * 40) * h / w) << "\">\n"
		  << "<title>grid vector map: " << vectors.size()
		  << " vectors (blue static, red dynamic, width = confidence)</title>\n"
		  << "<rect x=\"" << x0 - m << "\" y=\"" << -(y1 + m) << "\" width=\"" << w << "\" height=\"" << h
		  << "\" fill=\"white\"/>\n"
		  << "<g transform=\"scale(1,-1)\" stroke-linecap=\"round\">\n";
		for (const auto& v : vectors)
			f << "<line x1=\"" << v.start().x << "\" y1=\"" << v.start().y << "\" x2=\"" << v.end().x << "\" y2=\""
			  << v.end().y << "\" stroke=\"" << svgColour(v) << "\" stroke-width=\"" << svgStrokeWidth(v) << "\"/>\n";
		f << "</g>\n</svg>\n";
	});
}

void MapExport::write3DScene(const std::vector<GridVector>& vectors, const mrpt::maps::COccupancyGridMap2D& grid,
							 const std::string& path)
{
	mrpt::opengl::COpenGLScene scene;
	auto gridObj = mrpt::opengl::CSetOfObjects::Create();
	grid.getVisualizationInto(*gridObj);
	gridObj->setName("occupancy (Eq. 6)");
	scene.insert(gridObj);
	std::map<uint32_t, mrpt::opengl::CSetOfLines::Ptr> byColour;  // one line set per colour
	for (const auto& v : vectors)
	{
		const auto c = rgbOf(v);
		const uint32_t key = (uint32_t(c.R) << 16) | (uint32_t(c.G) << 8) | c.B;
		auto& lines = byColour[key];
		if (!lines)
		{
			lines = mrpt::opengl::CSetOfLines::Create();
			lines->setColor_u8(c);
			lines->setLineWidth(2.0f);
			lines->setName("grid vectors");
		}
		lines->appendLine(v.start().x, v.start().y, 0.01, v.end().x, v.end().y, 0.01);
	}
	for (auto& kv : byColour) scene.insert(kv.second);
	io::writeArchiveFile(path, true, [&](mrpt::serialization::CArchive& ar) { ar << scene; });  // as saveToFile
}

}  // namespace gridvector
