// Output files that appear complete or not at all: write to a temporary file in
// the target's directory, then rename it over the target.
#pragma once

#include <fstream>
#include <functional>
#include <string>

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

}  // namespace gridvector::io
