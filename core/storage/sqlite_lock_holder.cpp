#include "core/storage/sqlite_lock_holder.h"

#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>

namespace tt::storage {

namespace {

/// The WAL index's write lock: WALINDEX_LOCK_OFFSET (120) + WAL_WRITE_LOCK (0), sqlite3 src/wal.c.
constexpr unsigned long long kWalWriteLockByte = 120;

template <typename T>
bool number(std::string_view text, T& value, int base = 10) {
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value, base);
    return error == std::errc() && end == text.data() + text.size();
}

/// "fe:00:10961077" -> device and inode.
bool fileId(std::string_view text, FileLock& lock) {
    const std::size_t a = text.find(':');
    const std::size_t b = a == std::string_view::npos ? a : text.find(':', a + 1);
    if (b == std::string_view::npos) return false;
    return number(text.substr(0, a), lock.major, 16) && number(text.substr(a + 1, b - a - 1), lock.minor, 16) &&
           number(text.substr(b + 1), lock.inode);
}

/// The process's name from /proc/<pid>/comm ("?" when it is gone).
std::string processName(long pid) {
    std::ifstream comm("/proc/" + std::to_string(pid) + "/comm");
    std::string name;
    std::getline(comm, name);
    return name.empty() ? "?" : name;
}

/// Other processes' write locks on `path` that cover `byte` (any byte when `anyByte`).
std::vector<long> writers(const std::vector<FileLock>& locks, const std::string& path, unsigned long long byte,
                          bool anyByte) {
    struct stat st {};
    std::vector<long> pids;
    if (::stat(path.c_str(), &st) != 0) return pids;
    for (const FileLock& l : locks)
        if (l.write && l.pid != ::getpid() && l.major == ::major(st.st_dev) && l.minor == ::minor(st.st_dev) &&
            l.inode == st.st_ino && (anyByte || (l.start <= byte && byte <= l.end)))
            pids.push_back(l.pid);
    return pids;
}

}  // namespace

std::vector<FileLock> parseProcLocks(std::string_view procLocks) {
    std::vector<FileLock> locks;
    std::istringstream lines{std::string(procLocks)};
    std::string line;
    while (std::getline(lines, line)) {
        std::istringstream fields(line);
        std::string id, kind, mode, access, pid, file, start, end;
        if (!(fields >> id >> kind) || kind != "POSIX") continue;  // also "->" waiters and FLOCK/OFDLCK
        if (!(fields >> mode >> access >> pid >> file >> start >> end)) continue;
        FileLock lock;
        lock.write = access == "WRITE";
        if (!number(std::string_view(pid), lock.pid) || !fileId(file, lock) ||
            !number(std::string_view(start), lock.start))
            continue;
        if (end == "EOF")
            lock.end = ~0ULL;
        else if (!number(std::string_view(end), lock.end))
            continue;
        locks.push_back(lock);
    }
    return locks;
}

std::string sqliteLockHolder(const std::string& path) {
    std::ifstream file("/proc/locks");
    if (!file) return {};
    std::ostringstream text;
    text << file.rdbuf();
    const std::vector<FileLock> locks = parseProcLocks(text.str());
    std::vector<long> pids = writers(locks, path, 0, true);
    const std::vector<long> wal = writers(locks, path + "-shm", kWalWriteLockByte, false);
    pids.insert(pids.end(), wal.begin(), wal.end());
    std::sort(pids.begin(), pids.end());
    pids.erase(std::unique(pids.begin(), pids.end()), pids.end());
    std::string holders;
    for (long pid : pids)
        holders += (holders.empty() ? "" : ", ") + ("process " + std::to_string(pid) + " (" + processName(pid) + ")");
    return holders;
}

}  // namespace tt::storage
