// Hold still, then average, on the samples' own time stamps.
#include "core/calibration/settled_average.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace tt::core {
namespace {

TEST(SettledAverage, DropsTheSettlingThenAveragesUntilTheCountOrTheWindow) {
    SettledAverage byCount(0.5, 3);
    byCount.start();
    byCount.add(10.0, 100.0);  // the clock starts at the first sample: 10.0 .. 10.5 settles
    byCount.add(10.4, 100.0);
    EXPECT_EQ(byCount.phase(), SettledAverage::Phase::HoldStill);
    byCount.add(10.5, 1.0);
    byCount.add(10.6, 2.0);
    EXPECT_EQ(byCount.phase(), SettledAverage::Phase::Averaging);
    byCount.add(10.7, 6.0);
    EXPECT_EQ(byCount.phase(), SettledAverage::Phase::Done);
    EXPECT_EQ(byCount.count(), 3);
    EXPECT_DOUBLE_EQ(byCount.mean(), 3.0);
    EXPECT_DOUBLE_EQ(byCount.progress(), 1.0);

    SettledAverage byWindow(1.0, 100, 2.0);
    byWindow.start();
    byWindow.observe(0.0);
    byWindow.add(1.5, 4.0);
    EXPECT_NEAR(byWindow.progress(), 0.2 + 0.8 * 0.25, 1e-12);  // settled, a quarter of the window
    byWindow.observe(3.0);
    EXPECT_EQ(byWindow.phase(), SettledAverage::Phase::Done);
    EXPECT_EQ(byWindow.count(), 1);
    byWindow.start();  // a new step forgets the old values
    EXPECT_EQ(byWindow.count(), 0);
    EXPECT_THROW(SettledAverage(-1.0, 3), std::invalid_argument);
    EXPECT_THROW(SettledAverage(0.1, 0), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
