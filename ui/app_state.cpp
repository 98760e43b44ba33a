#include "ui/app_state.h"

#include <QCoreApplication>

namespace tt::ui {

AppState::AppState(QObject* parent) : QObject(parent) {}

void AppState::setLoop(Loop loop, const QString& detail) {
    if (loop == m_loop && detail == m_loopDetail) return;
    m_loop = loop;
    m_loopDetail = detail;
    emit loopChanged();
}

void AppState::setDevices(Tone tone, const QString& summary) {
    if (tone == m_deviceTone && summary == m_deviceSummary) return;
    m_deviceTone = tone;
    m_deviceSummary = summary;
    emit devicesChanged();
}

void AppState::setDatabaseDescription(const QString& description) {
    if (description == m_databaseDescription) return;
    m_databaseDescription = description;
    emit databaseChanged();
}

void AppState::setPlantLink(const QString& text, bool warns) {
    if (text == m_plantLink && warns == m_plantLinkWarns) return;
    m_plantLink = text;
    m_plantLinkWarns = warns;
    emit databaseChanged();
}

void AppState::setOperatorName(const QString& name) {
    if (name == m_operatorName) return;
    m_operatorName = name;
    emit operatorChanged();
}

QString AppState::loopName(Loop loop) {
    switch (loop) {
        case Loop::Idle:
            return QCoreApplication::translate("tt::ui::AppState", "Idle");
        case Loop::Running:
            return QCoreApplication::translate("tt::ui::AppState", "Running");
        case Loop::Paused:
            return QCoreApplication::translate("tt::ui::AppState", "Paused");
        case Loop::Fault:
            return QCoreApplication::translate("tt::ui::AppState", "Fault");
    }
    return {};
}

}  // namespace tt::ui
