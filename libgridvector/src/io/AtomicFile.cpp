#include "io/AtomicFile.h"

#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace gridvector::io
{
namespace fs = std::filesystem;

namespace
{
std::string temporaryNameFor(const std::string& path)
{
	static std::atomic<unsigned> counter{0};
	const fs::path p(path);
	const std::string name =
		"." + p.filename().string() + ".tmp" + std::to_string(::getpid()) + "_" + std::to_string(counter++);
	return (p.parent_path() / name).string();
}

std::string errnoText() { return std::strerror(errno); }
}  // namespace

AtomicFile::AtomicFile(std::string path, Mode mode) : path_(std::move(path)), mode_(mode)
{
	if (path_.empty()) throw std::runtime_error("(empty path): cannot write (no file name given)");
	if (fs::is_directory(path_)) fail("it is a directory");
	tmp_ = temporaryNameFor(path_);
	const auto flags =
		mode_ == Mode::Text ? std::ios::out | std::ios::trunc : std::ios::out | std::ios::trunc | std::ios::binary;
	errno = 0;
	out_.open(tmp_, flags);
	if (!out_) fail(errno ? errnoText() : "cannot create a temporary file next to it");
	if (mode_ == Mode::External) out_.close();  // created: the directory is writable
}

AtomicFile::~AtomicFile()
{
	if (committed_) return;
	if (out_.is_open()) out_.close();
	std::error_code ec;
	fs::remove(tmp_, ec);
}

std::ostream& AtomicFile::stream()
{
	if (mode_ == Mode::External) throw std::logic_error("AtomicFile::stream() in External mode");
	return out_;
}

void AtomicFile::commit()
{
	if (committed_) return;
	if (mode_ != Mode::External)
	{
		out_.flush();
		if (!out_) fail("write error (disk full?)");
		out_.close();
		if (out_.fail()) fail("error while closing");
	}
	if (std::rename(tmp_.c_str(), path_.c_str()) != 0) fail(errnoText());
	committed_ = true;
}

void AtomicFile::fail(const std::string& reason) const
{
	throw std::runtime_error(path_ + ": cannot write (" + reason + ")");
}

void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& fill)
{
	AtomicFile f(path);
	fill(f.stream());
	f.commit();
}

void ensureWritableDirectory(const std::string& dir)
{
	std::error_code ec;
	if (!fs::exists(dir, ec)) fs::create_directories(dir, ec);
	if (ec) throw std::runtime_error(dir + ": cannot write (" + ec.message() + ")");
	if (!fs::is_directory(dir)) throw std::runtime_error(dir + ": cannot write (not a directory)");
	if (::access(dir.c_str(), W_OK | X_OK) != 0) throw std::runtime_error(dir + ": cannot write (" + errnoText() + ")");
}

namespace
{
/** dir without a trailing separator ("out/" -> "out"); "" is the current directory. */
fs::path directoryPath(const std::string& dir)
{
	fs::path p(dir.empty() ? "." : dir);
	return p.has_filename() ? p : p.parent_path();
}

/** The missing directories on the way to dir, deepest first. */
std::vector<fs::path> missingDirectories(const fs::path& dir)
{
	std::vector<fs::path> out;
	std::error_code ec;
	for (fs::path p = dir; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) out.push_back(p);
	return out;
}
}  // namespace

void checkWritableDirectory(const std::string& dir)
{
	const fs::path p = directoryPath(dir);
	const auto missing = missingDirectories(p);
	fs::path existing = missing.empty() ? p : missing.back().parent_path();
	if (existing.empty()) existing = ".";
	if (!fs::is_directory(existing)) throw std::runtime_error(dir + ": cannot write (" + std::strerror(ENOTDIR) + ")");
	if (::access(existing.c_str(), W_OK | X_OK) != 0)
		throw std::runtime_error(dir + ": cannot write (" + errnoText() + ")");
}

void checkWritableFile(const std::string& path)
{
	if (path.empty()) throw std::runtime_error("(empty path): cannot write (no file name given)");
	auto fail = [&](const std::string& reason) { throw std::runtime_error(path + ": cannot write (" + reason + ")"); };
	if (fs::is_directory(path)) fail("it is a directory");
	fs::path dir = fs::path(path).parent_path();
	if (dir.empty()) dir = ".";
	// the reasons opening the temporary file would give: ENOENT, ENOTDIR, then EACCES, EROFS
	struct stat st;
	if (::stat(dir.c_str(), &st) != 0) fail(errnoText());
	if (!S_ISDIR(st.st_mode)) fail(std::strerror(ENOTDIR));
	if (::access(dir.c_str(), W_OK | X_OK) != 0) fail(errnoText());
}

OutputDirectory::OutputDirectory(std::string dir, std::string marker) : dir_(std::move(dir)), marker_(std::move(marker))
{
	checkWritableDirectory(dir_);
}

const std::string& OutputDirectory::create()
{
	for (const auto& p : missingDirectories(directoryPath(dir_))) created_.push_back(p.string());
	ensureWritableDirectory(dir_);
	removeStaleMarker();
	return dir_;
}

std::string OutputDirectory::markerPath() const { return marker_.empty() ? "" : (fs::path(dir_) / marker_).string(); }

void OutputDirectory::removeStaleMarker() const
{
	if (marker_.empty()) return;
	const std::string path = markerPath();
	std::error_code ec;
	if (fs::is_directory(fs::symlink_status(path, ec)))
		throw std::runtime_error(path + ": cannot write (it is a directory)");
	if (!fs::remove(path, ec) && ec)
		throw std::runtime_error(path + ": cannot remove a previous run's file (" + ec.message() + ")");
}

OutputDirectory::~OutputDirectory()
{
	std::error_code ec;
	for (const auto& d : created_)
		if (fs::exists(d, ec) && (!fs::is_empty(d, ec) || ec || !fs::remove(d, ec))) break;
}

}  // namespace gridvector::io
