#pragma once

namespace tt::test {

/// How long a test waits for work that only a slow machine delays (a background task, a run, device threads,
/// a child process): 9 minutes, under the 10-minute CTest timeout of ./test.sh. A wait returns as soon as its
/// condition holds, so a long limit costs nothing on a correct run; a loaded CI (`ctest -j4` on 2 cores made
/// a 3-second task take more than 60 s) no longer fails a correct test, and a test that really hangs still
/// fails with its own message before CTest ends it. Never used to assert that something is fast.
inline constexpr int kPatientWaitMs = 9 * 60 * 1000;

}  // namespace tt::test
