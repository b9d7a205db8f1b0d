// atomic_write.h: a file replaced in one step, or not at all.
//
// Inputs:  path     target file ("-" writes to stdout)
//          bytes    the complete contents, or
//          produce  a function that appends the contents to the ByteSink it is given (io/byte_sink.h:
//                   a 1 MiB buffer drained with write(2)), so that the contents are never held whole
// The bytes go to a temporary file created next to `path` (same directory, so rename(2) is
// atomic), which is renamed onto `path` (and fsync'ed first when the environment has
// SHADETOOL_FSYNC=1, for durability across a power loss). On any error the temporary file is removed
// and an existing file at `path` is left untouched. The new file gets the usual 0666 & ~umask mode.
// Errors: shadetool::Error `PATH: cannot write: REASON` (a full disk included); an Error thrown by
// `produce` removes the temporary file too and is passed on unchanged.
//
// write_files_atomically: several files that belong together (a mesh and its report) committed
// together: every temporary file is written first; if any of them fails, all are removed and no
// file is replaced. Only then are they renamed into place, in order (a rename within a directory
// does not fail for want of space; should one fail anyway, the later temporaries are removed).
// Entries "-" are written to stdout last, after every rename (streamed too: a write error, EPIPE
// or ENOSPC, is `stdout: cannot write: REASON` once some bytes may have gone out).
//
// remove_temporaries_on_signals: installs handlers for SIGINT and SIGTERM (only where the
// disposition is still the default one: a host that handles them itself, Python, keeps its own)
// that unlink every temporary being written at that moment and then re-raise the signal with the
// default action, so the process ends with the signal's status and an interrupted write leaves
// no `PATH.tmp-XXXXXX` behind (the existing file at PATH is untouched: it is only ever replaced
// by rename). Async-signal-safe: the temporaries are kept in a small fixed table of names (256
// slots of PATH_MAX bytes; a write that finds the table full, or a longer name, is simply not
// cleaned up on a signal), the handler calls only unlink, sigaction and raise. Idempotent.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <shadetool/io/byte_sink.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool::io {

void write_file_atomically(const std::string& path, std::string_view bytes);
void write_file_atomically(const std::string& path, const ProduceBytes& produce);

struct FileToWrite {
  std::string path;  // "-": stdout
  std::string_view bytes;
  ProduceBytes produce = nullptr;  // when set: the contents, streamed (`bytes` is not used)
};
void write_files_atomically(const std::vector<FileToWrite>& files);

void remove_temporaries_on_signals();

}  // namespace shadetool::io
#pragma GCC visibility pop
