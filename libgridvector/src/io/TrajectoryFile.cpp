#include <gridvector/io/AtomicFile.h>
#include <gridvector/io/FileBytes.h>
#include <gridvector/io/LogReader.h>
#include <gridvector/io/TextParsing.h>

#include <cstdio>

namespace gridvector::io
{
Trajectory readTrajectory(const std::string& path)
{
	const std::vector<char> text = readFileBytes(path);
	Trajectory out;
	LineCursor cur(text);
	std::string_view line;
	TextPos pos{path, 0};
	while (cur.next(line))
	{
		pos.line = cur.lineNumber();
		const auto t = splitTokens(line);
		if (t.empty() || t[0][0] == '#') continue;
		if (t.size() < 4) parseError(pos, "expected 't x y theta', found " + std::to_string(t.size()) + " fields");
		out.emplace_back(parseDouble(t[0], pos, "t"),
						 mrpt::math::TPose2D(parseDouble(t[1], pos, "x"), parseDouble(t[2], pos, "y"),
											 parseDouble(t[3], pos, "theta")));
	}
	return out;
}

void writeTrajectory(const std::string& path, const Trajectory& traj)
{
	AtomicFile f(path);
	std::ostream& os = f.stream();
	char buf[160];
	for (const auto& [t, p] : traj)
	{
		std::snprintf(buf, sizeof buf, "%.6f %.6f %.6f %.6f\n", t, p.x, p.y, p.phi);
		os << buf;
	}
	f.commit();
}

}  // namespace gridvector::io
