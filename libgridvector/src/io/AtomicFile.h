// Output files that appear complete or not at all: write to a temporary file in
// the target's directory, then rename it over the target.
#pragma once

#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace gridvector::io
{
/** One atomically written output file.
 *
 * Text mode: write to stream(), then commit(). External mode: a writer that
 * opens files itself (e.g. a gzip stream) writes to tempPath(), then commit().
 * If commit() is never reached (an exception), the destructor removes the
 * temporary file and the target is left untouched. Every failure throws
 * std::runtime_error("path: cannot write (reason)"). */
class AtomicFile
{
   public:
	enum class Mode
	{
		Text,  //!< stream() is an open std::ofstream on the temporary file
		Binary,  //!< as Text, opened in binary mode
		External  //!< the caller writes tempPath() itself
	};

	explicit AtomicFile(std::string path, Mode mode = Mode::Text);
	~AtomicFile();
	AtomicFile(const AtomicFile&) = delete;
	AtomicFile& operator=(const AtomicFile&) = delete;

	std::ostream& stream();
	const std::string& path() const { return path_; }
	const std::string& tempPath() const { return tmp_; }

	/** Flushes, checks for write errors and renames the temporary file over path(). */
	void commit();

   private:
	[[noreturn]] void fail(const std::string& reason) const;

	std::string path_;
	std::string tmp_;
	Mode mode_;
	std::ofstream out_;
	bool committed_ = false;
};

/** Writes path atomically with what fill() puts into the stream. */
void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& fill);

/** Throws "dir: cannot write (reason)" unless dir exists (or can be created) and is writable. */
void ensureWritableDirectory(const std::string& dir);

/** As ensureWritableDirectory, but creates nothing: dir is a writable directory, or its nearest
 * existing ancestor is one (so that dir can be created). */
void checkWritableDirectory(const std::string& dir);

/** Throws "path: cannot write (reason)", with the reason AtomicFile(path) would give, unless
 * path can be written atomically: it is not a directory and its directory exists and is
 * writable. Creates nothing: a tool calls it before a long read, not after. */
void checkWritableFile(const std::string& path);

/** A tool's output directory, created only when there is something to write into it.
 *
 * The constructor checks that dir can be written (checkWritableDirectory: a run fails before its
 * work, not after); create() makes it just before the first output file. If the run fails after
 * create() (an exception before any file was committed), the destructor removes the directories
 * create() made that are still empty: a failed run leaves no new empty directory behind.
 *
 * An output set (doc/io.md, "Output sets"): `marker` (e.g. "report.json") is the file the tool
 * writes last, once every other output is in place, so a directory with it is complete.
 * create() removes a previous run's marker before any output is rewritten: a run that fails
 * halfway leaves a directory without one, never a mixed set that looks complete. */
class OutputDirectory
{
   public:
	explicit OutputDirectory(std::string dir, std::string marker = "");
	~OutputDirectory();
	OutputDirectory(const OutputDirectory&) = delete;
	OutputDirectory& operator=(const OutputDirectory&) = delete;

	/** Creates the directory (and missing parents) if needed, removes a previous marker; returns path(). */
	const std::string& create();
	const std::string& path() const { return dir_; }
	/** dir/marker, the file to write last ("" without a marker). */
	std::string markerPath() const;

   private:
	void removeStaleMarker() const;

	std::string dir_, marker_;
	std::vector<std::string> created_;  //!< made by create(), deepest first
};

}  // namespace gridvector::io
