#include "EmOutputs.h"

#include <gridvector/Version.h>
#include "io/AtomicFile.h"
#include "io/JsonFile.h"

#include "map/GlobalMap.h"
#include <mrpt/maps/CGridVectorMap.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>

namespace gridvector::app
{
bool writeEdgeDump(const std::string& path, const std::map<EdgeKey, Constraint>& edges, const std::vector<size_t>& key,
				   const std::function<Eigen::Matrix3d(const Constraint&)>& information)
{
	std::FILE* f = std::fopen(path.c_str(), "w");
	if (!f) return false;
	std::fprintf(
		f,
		"# from to kind rejected dof degeneracy rms matched_length correspondences x y phi I00 I01 I02 I11 I12 I22\n");
	for (const auto& [k, c] : edges)
	{
		const Eigen::Matrix3d I = information(c);
		std::fprintf(f, "%zu %zu %s %d %d %.4g %.4g %.4g %zu %.6f %.6f %.6f %.6g %.6g %.6g %.6g %.6g %.6g\n",
					 key[c.from], key[c.to], toString(c.kind), int(c.rejected), c.dof, c.degeneracy, c.rms,
					 c.matchedLength, c.correspondences.size(), c.z.x, c.z.y, c.z.phi, I(0, 0), I(0, 1), I(0, 2),
					 I(1, 1), I(1, 2), I(2, 2));
	}
	std::fclose(f);
	return true;
}

void writeVectors(const std::string& path, const std::vector<GridVector>& vectors)
{
	io::writeFileAtomically(path, [&](std::ostream& o) {
		o << "# x1 y1 x2 y2 p_static state (gv-em-slam final merged map)\n" << std::fixed << std::setprecision(4);
		for (const auto& v : vectors)
			o << v.start().x << ' ' << v.start().y << ' ' << v.end().x << ' ' << v.end().y << ' ' << v.pStatic() << ' '
			  << (v.state == VectorState::Dynamic ? "dynamic" : "static") << '\n';
	});
}

void writeSvg(const std::string& path, const std::vector<GridVector>& vectors, const std::vector<Door>& doors,
			  const std::vector<mrpt::math::TPose2D>& poses)
{
	double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
	auto grow = [&](double x, double y) {
		x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
	};
	for (const auto& v : vectors) grow(v.start().x, v.start().y), grow(v.end().x, v.end().y);
	for (const auto& p : poses) grow(p.x, p.y);
	if (x0 > x1) x0 = y0 = 0, x1 = y1 = 1;
	const double m = 1.0;
	io::writeFileAtomically(path, [&](std::ostream& o) {
		o << std::fixed << std::setprecision(3);
		o << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << x0 - m << ' ' << -(y1 + m) << ' '
		  << (x1 - x0 + 2 * m) << ' ' << (y1 - y0 + 2 * m) << "\" width=\"" << int(50 * (x1 - x0 + 2 * m))
		  << "\" height=\"" << int(50 * (y1 - y0 + 2 * m)) << "\">\n<g transform=\"scale(1,-1)\">\n";
		o << "<rect x=\"" << x0 - m << "\" y=\"" << y0 - m << "\" width=\"" << x1 - x0 + 2 * m << "\" height=\""
		  << y1 - y0 + 2 * m << "\" fill=\"white\"/>\n";
		if (!poses.empty())
		{
			o << "<polyline fill=\"none\" stroke=\"#aaaaaa\" stroke-width=\"0.02\" points=\"";
			for (const auto& p : poses) o << p.x << ',' << p.y << ' ';
			o << "\"/>\n";
		}
		for (const auto& v : vectors)
			o << "<line x1=\"" << v.start().x << "\" y1=\"" << v.start().y << "\" x2=\"" << v.end().x << "\" y2=\""
			  << v.end().y << "\" stroke=\"" << (v.state == VectorState::Dynamic ? "red" : "blue")
			  << "\" stroke-width=\"0.05\"/>\n";
		for (const auto& d : doors)
		{
			o << "<circle cx=\"" << d.hinge.x << "\" cy=\"" << d.hinge.y << "\" r=\"0.12\" fill=\"green\"/>\n";
			for (double a : d.angles)
				o << "<line x1=\"" << d.hinge.x << "\" y1=\"" << d.hinge.y << "\" x2=\""
				  << d.hinge.x + d.length * std::cos(a) << "\" y2=\"" << d.hinge.y + d.length * std::sin(a)
				  << "\" stroke=\"green\" stroke-width=\"0.06\" stroke-dasharray=\"0.1,0.05\"/>\n";
		}
		o << "</g>\n</svg>\n";
	});
}

void writeDoors(const std::string& path, const std::vector<Door>& doors)
{
	io::writeFileAtomically(path, [&](std::ostream& o) {
		o << "# hinge_x hinge_y length angle_min angle_max states (Sec. 5.4; angles: leaf directions, rad)\n"
		  << std::fixed << std::setprecision(4);
		for (const auto& d : doors)
			o << d.hinge.x << ' ' << d.hinge.y << ' ' << d.length << ' ' << d.angles.front() << ' ' << d.angles.back()
			  << ' ' << d.angles.size() << '\n';
	});
}

void writeDoorStates(const std::string& path, const std::vector<Door>& doors)
{
	io::writeFileAtomically(path, [&](std::ostream& o) {
		o << "# hinge_x hinge_y length angle_min angle_max states | W wall x1 y1 x2 y2 | leaves (indices into "
			 "vectors.txt) | A state directions [deg] (Sec. 5.4, Fig. 10)\n"
		  << std::fixed << std::setprecision(4);
		for (const auto& d : doors)
		{
			o << d.hinge.x << ' ' << d.hinge.y << ' ' << d.length << ' ' << d.angles.front() << ' ' << d.angles.back()
			  << ' ' << d.angles.size() << " | W " << d.wallStart.x << ' ' << d.wallStart.y << ' ' << d.wallEnd.x << ' '
			  << d.wallEnd.y << " |";
			for (size_t leaf : d.leaves) o << ' ' << leaf;
			o << " | A" << std::setprecision(1);
			for (double a : d.angles) o << ' ' << a * 180 / M_PI;
			o << std::setprecision(4) << '\n';
		}
	});
}

void writeGvmap(const std::string& path, const GridVectorConfig& cfg, const std::vector<GridVector>& vectors)
{
	mrpt::maps::CGridVectorMap map(cfg);
	map.globalMap().setVectors(vectors);
	map.saveToFile(path);
}

namespace
{
nlohmann::ordered_json iterationJson(const EmIteration& it)
{
	const auto& m = it.mstep;
	return {{"iteration", it.index},
			{"changed_share", it.changedShare},
			{"constraints", m.constraints},
			{"edges_active", m.active},
			{"edges_sequential", m.sequential},
			{"edges_overlap", m.overlap},
			{"edges_loop", m.loop},
			{"added", m.added},
			{"removed", m.removed},
			{"recomputed", m.recomputed},
			{"registrations", m.registrations},
			{"failed_registrations", m.failedRegistrations},
			{"unverified", m.unverified},
			{"rejected_by_residual", m.optimisation.rejected},
			{"optimiser_iterations", m.optimisation.iterations},
			{"static_vectors", it.staticVectors},
			{"dynamic_vectors", it.dynamicVectors},
			{"static_length_m", it.staticLength},
			{"dynamic_length_m", it.dynamicLength},
			{"changed_vectors", it.changedVectors},
			{"m_seconds", it.mSeconds},
			{"registration_seconds", m.registrationSeconds},
			{"update_seconds", m.updateSeconds},
			{"overlap_seconds", m.overlapSeconds},
			{"loop_search_seconds", m.loopSeconds},
			{"loop_searches", m.loopSearches},
			{"passes_beyond_bound", m.passesBeyondBound},
			{"optimisation_seconds", m.optimisation.seconds},
			{"e_seconds", it.eSeconds},
			{"wipe_seconds", it.wipeSeconds},
			{"classify_seconds", it.classifySeconds},
			{"doors", it.doors.doors},
			{"doors_found", it.doors.found},
			{"door_vectors_excluded", it.doors.excluded},
			{"door_vectors_cut", it.doors.cut},
			{"door_seconds", it.doors.seconds}};
}

nlohmann::ordered_json finalMapJson(const std::vector<GridVector>& vectors, size_t doors)
{
	size_t ns = 0, nd = 0;
	double ls = 0, ld = 0;
	for (const auto& v : vectors)
		(v.state == VectorState::Dynamic ? nd : ns)++, (v.state == VectorState::Dynamic ? ld : ls) += v.length();
	return {{"static_vectors", ns},
			{"dynamic_vectors", nd},
			{"static_length_m", ls},
			{"dynamic_length_m", ld},
			{"doors", doors}};
}
// NaN (a graph without redundancy) is written as null by io::writeJsonFile.
nlohmann::ordered_json selfCheckJson(const SelfCheckEvidence& e, const SelfCheckVerdict& v)
{
	const PoseGraphFit& g = e.graph;
	return {{"verdict", v.ok ? "ok" : "suspect"},
			{"reasons", v.reasons},
			{"converged", e.converged},
			{"iterations", e.iterations},
			{"registrations", e.registrations},
			{"failed_registrations", e.failedRegistrations},
			{"failed_share", e.failedShare()},
			{"registration_edges", e.edges},
			{"rejected_edges", e.rejectedEdges},
			{"rejected_share", e.rejectedShare()},
			{"normalised_chi2", g.normalisedChi2()},
			{"keyframes", e.keyframes},
			{"sequential_edges", e.sequentialEdges},
			{"unlinked_share", e.unlinkedShare()},
			{"dynamic_share", e.dynamicShare()},
			{"graph",
			 {{"nodes", g.nodes},
			  {"odometry_edges", g.odometryEdges},
			  {"registration_edges", g.registrationEdges},
			  {"odometry_chi2", g.odometryChi2},
			  {"registration_chi2", g.registrationChi2},
			  {"odometry_dof", g.odometryDof},
			  {"registration_dof", g.registrationDof},
			  {"downweighted", g.downweighted},
			  {"inactive", g.inactive}}},
			{"beams", e.beams.beams},
			{"beams_through_walls", e.beams.throughWalls},
			{"beams_through_occupied", e.beams.throughOccupied},
			{"through_wall_share", e.beams.share()},
			{"through_wall_geometric_share", e.beams.geometricShare()}};
}
}  // namespace

void writeReport(const std::string& path, const RunFigures& run, const EmResult& res)
{
	nlohmann::ordered_json r;
	r["version"] = {{"gridvector", version()}, {"git", gitDescription()}, {"mrpt", mrptVersion()}};
	r["input"] = run.input;
	r["init"] = run.init.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(run.init);
	r["config"] = nlohmann::ordered_json::parse(run.configJson);
	r["scans"] = run.scans;
	r["local_vectors"] = run.localVectors;
	r["keyframes"] = res.keyframes;
	r["iterations_run"] = res.iterations.size();
	r["converged"] = res.converged;
	r["self_check"] = selfCheckJson(run.selfCheck, run.verdict);
	r["iterations"] = nlohmann::ordered_json::array();
	for (const auto& it : res.iterations) r["iterations"].push_back(iterationJson(it));
	if (!run.onlineJson.empty()) r["online"] = nlohmann::ordered_json::parse(run.onlineJson);
	r["final_map"] = finalMapJson(res.finalVectors, run.doors);
	r["memory"] = MemoryAccounting::toJson(run.memory);
	r["seconds"] = {{"read", run.readSeconds},
					{"extract", run.extractSeconds},
					{"em", run.emSeconds},
					{"final_map", res.finalMapSeconds},
					{"final_merge", res.finalMergeSeconds},
					{"doors", res.doorSeconds},
					{"outputs", run.outputSeconds},
					{"total", run.totalSeconds}};
	io::writeJsonFile(path, r);
}

}  // namespace gridvector::app
