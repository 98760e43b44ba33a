#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace tt::storage {

/// One POSIX lock of /proc/locks: who holds it, on which file, which bytes.
struct FileLock {
    long pid = 0;
    bool write = false;
    unsigned major = 0, minor = 0;  ///< the file's device
    unsigned long inode = 0;
    unsigned long long start = 0, end = 0;  ///< byte range, inclusive (EOF: the largest value)
};

/// The granted POSIX locks listed in `procLocks` (the text of /proc/locks; waiting requests, "->",
/// and other kinds are left out). Malformed lines are skipped.
std::vector<FileLock> parseProcLocks(std::string_view procLocks);

/// Who holds the write lock of the SQLite file `path`, read from /proc/locks (Linux): a write lock on
/// the file itself (rollback journal) or on the write-lock byte of its WAL index `path-shm`; as
/// "process 1234 (sqlite3)", several joined with ", ". Empty when no other process holds it or it
/// cannot be found out (no /proc, a network file system).
std::string sqliteLockHolder(const std::string& path);

}  // namespace tt::storage
