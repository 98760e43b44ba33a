#include "ui/pages/plant_page.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QStackedWidget>
#include <QTableView>
#include <QTimer>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include "ui/empty_state.h"
#include "ui/pages/planned_page.h"
#include "ui/plant/plant_model.h"

namespace tt::ui {

namespace {

/// Reads the overview with a connection of this (worker) thread, read-only.
PlantRefresh readPlant(storage::DatabaseConfig config) {
    PlantRefresh r;
    try {
        config.readOnly = config.kind == storage::DatabaseConfig::Kind::Postgres;
        storage::Database db(config);
        r.overview = runtime::plantOverview(db);
    } catch (const std::exception& e) {
        r.error = QString::fromUtf8(e.what());
    }
    return r;
}

}  // namespace

PlantPage::PlantPage(AppContext& context, QWidget* parent)
    : Page(PageId::Plant, context, parent),
      m_model(new PlantModel(this)),
      m_source(new QLabel(this)),
      m_status(new QLabel(this)),
      m_refresh(new QPushButton(this)),
      m_stack(new QStackedWidget(this)),
      m_empty(new EmptyState(this)),
      m_table(new QTableView(this)),
      m_hint(new QLabel(this)),
      m_timer(new QTimer(this)) {
    m_source->setObjectName(QStringLiteral("plantSource"));
    m_status->setObjectName(QStringLiteral("plantStatus"));
    m_refresh->setObjectName(QStringLiteral("plantRefresh"));
    m_table->setObjectName(QStringLiteral("plantTable"));
    m_hint->setObjectName(QStringLiteral("plantHint"));
    m_source->setWordWrap(true);
    m_status->setWordWrap(true);
    m_hint->setWordWrap(true);
    m_table->setModel(m_model);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setWordWrap(false);
    m_table->verticalHeader()->setVisible(false);
    m_table->verticalHeader()->setDefaultSectionSize(52);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(false);
    m_table->setStyleSheet(QStringLiteral("QTableView { font-size: 15pt; }"));
    m_stack->addWidget(m_empty);
    m_stack->addWidget(m_table);

    auto* top = new QHBoxLayout;
    top->addWidget(m_source, 1);
    top->addWidget(m_status, 1);
    top->addWidget(m_refresh);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(16, 8, 16, 8);
    layout->addLayout(top);
    layout->addWidget(m_stack, 1);
    layout->addWidget(m_hint);

    m_timer->setInterval(kRefreshMs);
    connect(m_timer, &QTimer::timeout, this, &PlantPage::refresh);
    connect(m_refresh, &QPushButton::clicked, this, &PlantPage::refresh);
    connect(&m_watcher, &QFutureWatcher<PlantRefresh>::finished, this, &PlantPage::finished);
    connect(m_table, &QTableView::clicked, this, [this](const QModelIndex& index) {
        const QString machine = m_model->machineAt(index.row());
        if (!machine.isEmpty()) emit reportsRequested(machine);
    });
    retranslate();
}

PlantPage::~PlantPage() {
    m_timer->stop();
    m_watcher.waitForFinished();
}

void PlantPage::setRefreshMs(int ms) {
    m_timer->setInterval(ms);
}

int PlantPage::refreshMs() const {
    return m_timer->interval();
}

QString PlantPage::title() const {
    return pageTitle(PageId::Plant);
}

void PlantPage::retranslate() {
    m_refresh->setText(tr("Refresh"));
    m_hint->setText(tr("Click a machine to open its reports. Cpk of the last %1 parts per control point, ▲▼ its "
                       "change against the %1 before; the page reads the plant database every %2 s.")
                        .arg(runtime::kPlantWindowParts)
                        .arg(kRefreshMs / 1000));
    QString where;
    try {
        where = context().data().config().describe();
    } catch (const std::exception&) {
        where = tr("none");
    }
    m_source->setText(tr("Plant database: %1").arg(where));
    m_empty->setTexts(tr("No machine has written to the plant database yet"),
                      m_error.isEmpty()
                          ? tr("Every terminal that stores its runs here appears with its state, the parts it still "
                               "keeps, today's verdicts, the capability of its last parts and its open alarms.")
                          : m_error);
    showStatus();
}

void PlantPage::showEvent(QShowEvent* event) {
    Page::showEvent(event);
    m_timer->start();
    refresh();
}

void PlantPage::hideEvent(QHideEvent* event) {
    m_timer->stop();
    Page::hideEvent(event);
}

void PlantPage::refresh() {
    if (busy()) return;
    storage::DatabaseConfig config;
    try {
        config = context().data().config();
    } catch (const std::exception& e) {
        m_error = QString::fromUtf8(e.what());
        retranslate();
        emit refreshed();
        return;
    }
    m_status->setText(tr("Reading the plant database…"));
    m_watcher.setFuture(QtConcurrent::run(readPlant, config));
}

void PlantPage::finished() {
    const PlantRefresh r = m_watcher.result();
    m_error = r.error;
    if (r.error.isEmpty()) {
        m_readAt = QDateTime::currentDateTime();
        m_model->setOverview(r.overview);
    }
    m_stack->setCurrentWidget(m_model->rowCount() > 0 ? static_cast<QWidget*>(m_table) : m_empty);
    retranslate();
    emit refreshed();
}

void PlantPage::showStatus() {
    if (!m_error.isEmpty())
        m_status->setText(tr("Cannot read the plant database: %1").arg(m_error));
    else if (m_readAt.isValid())
        m_status->setText(tr("Read at %1: %n machine(s)", nullptr, m_model->rowCount())
                              .arg(m_readAt.toString(QStringLiteral("HH:mm:ss"))));
    else
        m_status->setText(QString());
}

}  // namespace tt::ui
