// Exports of the global map: occupancy images (PNG, ROS map_server), vectors (text, SVG), MRPT 3D scene.
#pragma once

#include <gridvector/GridVector.h>

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <string>
#include <vector>

namespace gridvector
{
/** Every writer is atomic (temporary file + rename: a reader never sees a
 * half-written file) and throws std::runtime_error("path: cannot write (...)"). */
class MapExport
{
   public:
	/** Occupancy image (MRPT's COccupancyGridMap2D::saveAsBitmapFile: white free, black occupied, grey unknown). */
	static void writePng(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& path);

	/** ROS map_server map: binary PGM (P5, first row = top = largest y, pixel
	 * 255 (1 - p_occupied), unknown 0.5 -> 128) and its YAML (image, resolution,
	 * origin of the lower-left pixel, negate 0, occupied_thresh 0.65,
	 * free_thresh 0.196, mode trinary). The YAML names the PGM by file name. */
	static void writeRosMap(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& pgmPath,
							const std::string& yamlPath);

	/** `x1 y1 x2 y2 p_static` per vector (one header comment line). */
	static void writeVectorsText(const std::vector<GridVector>& vectors, const std::string& path);

	/** SVG of the vectors in metres (y up): static blue, dynamic red, vectors
	 * of unknown state coloured from red (p_static 0) to blue (1); stroke width
	 * grows with the confidence: p_static for static, 1 - p_static for
	 * dynamic, |2 p_static - 1| for unknown. */
	static void writeSvg(const std::vector<GridVector>& vectors, const std::string& path);
	/** The stroke colour and width (metres) writeSvg uses for a vector. */
	static std::string svgColour(const GridVector& v);
	static double svgStrokeWidth(const GridVector& v);

	/** mrpt::opengl::COpenGLScene (gzip-serialised, for SceneViewer3D):
	 * the occupancy grid as a textured plane and the vectors as coloured lines
	 * (as in the SVG) 1 cm above it. */
	static void write3DScene(const std::vector<GridVector>& vectors, const mrpt::maps::COccupancyGridMap2D& grid,
							 const std::string& path);
};

}  // namespace gridvector
