// The plant database's link in the operator's words (issue 24, item 2): near the journal's bound (90 %) the
// operator is warned, at it the loop takes no new part and says so; the command line's line (ForwarderStatus::
// describe) says the same.
#include <gtest/gtest.h>

#include "core/storage/plant_forwarder.h"
#include "ui/run/plant_link_text.h"

namespace tt::ui {
namespace {

storage::ForwarderStatus journalAt(std::int64_t usedMiB, std::int64_t limitMiB) {
    storage::ForwarderStatus s;
    s.link = storage::ForwarderStatus::Link::Online;
    s.backlogParts = 12;
    s.journalBytes = usedMiB * 1024 * 1024;
    s.journalLimitBytes = limitMiB * 1024 * 1024;
    return s;
}

TEST(PlantLinkText, TheOperatorIsWarnedNearTheJournalsBoundAndToldWhenItIsFull) {
    const storage::ForwarderStatus roomy = journalAt(899, 1000);
    EXPECT_FALSE(roomy.nearFull());
    EXPECT_FALSE(plantLinkWarns(roomy));
    EXPECT_FALSE(plantLinkText(roomy).contains(QStringLiteral("full")));

    const storage::ForwarderStatus near = journalAt(900, 1000);
    EXPECT_TRUE(near.nearFull());
    EXPECT_FALSE(near.full());
    EXPECT_TRUE(plantLinkWarns(near));
    EXPECT_TRUE(plantLinkText(near).contains(QStringLiteral("nearly full (900 of 1000 MiB)")))
        << plantLinkText(near).toStdString();
    EXPECT_TRUE(near.describe().contains(QStringLiteral("the journal is nearly full (900 of 1000 MiB)")))
        << near.describe().toStdString();

    const storage::ForwarderStatus full = journalAt(1000, 1000);
    EXPECT_TRUE(full.full());
    EXPECT_TRUE(plantLinkText(full).contains(QStringLiteral("the loop takes no new part")))
        << plantLinkText(full).toStdString();
    EXPECT_TRUE(full.describe().contains(QStringLiteral("the journal is full"))) << full.describe().toStdString();
}

}  // namespace
}  // namespace tt::ui
