#include "ui/run/plant_link_text.h"

#include <QCoreApplication>

namespace tt::ui {

namespace {

QString tr(const char* text) {
    return QCoreApplication::translate("tt::ui::PlantLink", text);
}

QString linkText(const storage::ForwarderStatus& s) {
    using Link = storage::ForwarderStatus::Link;
    const QString kept = QString::number(s.backlogParts);
    switch (s.link) {
        case Link::Offline:
            return tr("Plant database offline since %1; parts kept on this terminal: %2")
                .arg(s.offlineSince.toString(QStringLiteral("HH:mm")), kept);
        case Link::Starting:
            return tr("Plant database: connecting; parts kept on this terminal: %1").arg(kept);
        case Link::Online:
            break;
    }
    return s.drained ? tr("Plant database: every part sent")
                     : tr("Plant database: sending; parts kept on this terminal: %1").arg(kept);
}

}  // namespace

QString plantLinkText(const storage::ForwarderStatus& status) {
    const QString link = linkText(status);
    const auto mib = [](std::int64_t bytes) { return QString::number(bytes / (1024 * 1024)); };
    if (status.full())
        return tr("%1. The journal on this terminal is full (%2 of %3 MiB): the loop takes no new part until the "
                  "plant database has taken parts")
            .arg(link, mib(status.journalBytes), mib(status.journalLimitBytes));
    if (status.nearFull())
        return tr("%1. The journal on this terminal is nearly full (%2 of %3 MiB)")
            .arg(link, mib(status.journalBytes), mib(status.journalLimitBytes));
    return link;
}

bool plantLinkWarns(const storage::ForwarderStatus& status) {
    return status.link == storage::ForwarderStatus::Link::Offline || status.nearFull();
}

}  // namespace tt::ui
