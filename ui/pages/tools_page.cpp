#include "ui/pages/tools_page.h"

#include <QAction>
#include <QFile>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QPushButton>
#include <QStackedWidget>
#include <QTabWidget>
#include <QTableView>
#include <QUndoStack>
#include <QVBoxLayout>
#include <set>

#include "core/model/tool_table_csv.h"
#include "core/storage/tool_store.h"
#include "ui/app_state.h"
#include "ui/empty_state.h"
#include "ui/pages/planned_page.h"
#include "ui/prompt.h"
#include "ui/tools/choice_delegate.h"
#include "ui/tools/materials_model.h"
#include "ui/tools/tool_audit_model.h"
#include "ui/tools/tool_import_model.h"
#include "ui/tools/tool_table_model.h"

namespace tt::ui {

namespace {

QPushButton* button(QWidget* parent, const char* name, const char* role = nullptr) {
    auto* b = new QPushButton(parent);
    b->setObjectName(QLatin1String(name));
    if (role) b->setProperty("role", QLatin1String(role));
    return b;
}

QTableView* tableView(QWidget* parent, const char* name) {
    auto* v = new QTableView(parent);
    v->setObjectName(QLatin1String(name));
    v->verticalHeader()->setDefaultSectionSize(46);  // finger-sized rows
    v->horizontalHeader()->setMinimumSectionSize(70);
    v->setSelectionBehavior(QAbstractItemView::SelectRows);
    v->setWordWrap(false);
    return v;
}

}  // namespace

ToolsPage::ToolsPage(AppContext& context, QWidget* parent)
    : Page(PageId::Tools, context, parent),
      m_model(new ToolTableModel(this)),
      m_importModel(new ToolImportModel(this)),
      m_materialsModel(new MaterialsModel(this)),
      m_auditModel(new ToolAuditModel(this)),
      m_stack(new QStackedWidget(this)),
      m_editor(new QWidget(this)),
      m_preview(new QWidget(this)),
      m_storageProblem(new EmptyState(this)) {
    buildEditor();
    buildImportPreview();
    m_stack->addWidget(m_editor);
    m_stack->addWidget(m_preview);
    m_stack->addWidget(m_storageProblem);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(24, 16, 24, 16);
    layout->addWidget(m_stack);

    connect(m_model, &ToolTableModel::pendingChanged, this, &ToolsPage::updateState);
    connect(m_model, &ToolTableModel::editRefused, this,
            [this](int, int, const QString& reason) { showStatus(tr("Not accepted: %1").arg(reason), true); });
    connect(m_materialsModel, &MaterialsModel::materialEdited, this, &ToolsPage::onMaterialEdited);
    connect(m_materialsModel, &MaterialsModel::editRefused, this,
            [this](const QString& reason) { showStatus(tr("Not accepted: %1").arg(reason), true); });
    if (context.state) {
        m_model->setOperatorName(context.state->operatorName());
        connect(context.state, &AppState::operatorChanged, this,
                [this] { m_model->setOperatorName(this->context().state->operatorName()); });
    }
    openStore();
    retranslate();
}

ToolsPage::~ToolsPage() {
    // The models and the undo stack die with the page's children and signal on the way out.
    m_model->undoStack()->disconnect(this);
    m_model->disconnect(this);
}

QString ToolsPage::title() const {
    return pageTitle(PageId::Tools);
}

void ToolsPage::buildEditor() {
    m_add = button(m_editor, "toolAdd");
    m_remove = button(m_editor, "toolRemove");
    m_undo = button(m_editor, "toolUndo");
    m_redo = button(m_editor, "toolRedo");
    m_import = button(m_editor, "toolImport");
    m_export = button(m_editor, "toolExport");
    m_discard = button(m_editor, "toolDiscard", "danger");
    m_apply = button(m_editor, "toolApply", "primary");
    m_status = new QLabel(m_editor);
    m_status->setObjectName(QStringLiteral("toolStatus"));
    m_status->setWordWrap(true);
    m_status->setMinimumHeight(40);

    m_table = tableView(m_editor, "toolTable");
    m_table->setModel(m_model);
    m_table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                             QAbstractItemView::AnyKeyPressed | QAbstractItemView::SelectedClicked);
    m_table->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_table->setSelectionBehavior(QAbstractItemView::SelectItems);
    m_table->setItemDelegate(new ChoiceDelegate(
        {ToolTableModel::Section, ToolTableModel::Material},
        [this](const QModelIndex& index) {
            QList<QPair<QString, QString>> out;
            if (index.column() == ToolTableModel::Section) {
                out << qMakePair(tr("round"), QStringLiteral("round"))
                    << qMakePair(tr("rectangular"), QStringLiteral("rectangular"));
            } else {
                for (const core::Material& m : m_model->materials())
                    out << qMakePair(
                        tr("%1 (E %2 MPa)").arg(QString::fromStdString(m.name)).arg(m.youngsModulusMpa, 0, 'f', 0),
                        QString::fromStdString(m.name));
            }
            return out;
        },
        m_table));

    m_materialsView = tableView(m_editor, "materialsTable");
    m_materialsView->setModel(m_materialsModel);
    m_materialsView->setSelectionMode(QAbstractItemView::SingleSelection);
    m_materialsView->horizontalHeader()->setMinimumSectionSize(260);
    m_addMaterial = button(m_editor, "materialAdd");
    m_removeMaterial = button(m_editor, "materialRemove");
    m_materialsHint = new QLabel(m_editor);
    m_materialsHint->setWordWrap(true);
    auto* materialsPage = new QWidget(m_editor);
    auto* materialsButtons = new QHBoxLayout;
    materialsButtons->addWidget(m_addMaterial);
    materialsButtons->addWidget(m_removeMaterial);
    materialsButtons->addStretch(1);
    auto* materialsLayout = new QVBoxLayout(materialsPage);
    materialsLayout->addWidget(m_materialsHint);
    materialsLayout->addLayout(materialsButtons);
    materialsLayout->addWidget(m_materialsView, 1);

    m_auditView = tableView(m_editor, "auditTable");
    m_auditView->setModel(m_auditModel);
    m_auditView->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_auditView->horizontalHeader()->setStretchLastSection(true);

    m_tabs = new QTabWidget(m_editor);
    m_tabs->setObjectName(QStringLiteral("toolTabs"));
    m_tabs->setStyleSheet(QStringLiteral("QTabBar::tab { min-height: 40px; padding: 4px 22px; font-size: 14pt; }"));
    m_tabs->addTab(m_table, QString());
    m_tabs->addTab(materialsPage, QString());
    m_tabs->addTab(m_auditView, QString());

    auto* buttons = new QHBoxLayout;
    for (QPushButton* b : {m_add, m_remove, m_undo, m_redo, m_import, m_export})
        buttons->addWidget(b);
    buttons->addStretch(1);
    // Discard and Apply sit beside the message that counts the pending changes they act on.
    auto* pending = new QHBoxLayout;
    pending->addWidget(m_status, 1);
    pending->addWidget(m_discard);
    pending->addWidget(m_apply);
    auto* layout = new QVBoxLayout(m_editor);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(buttons);
    layout->addLayout(pending);
    layout->addWidget(m_tabs, 1);

    QUndoStack* undo = m_model->undoStack();
    connect(m_add, &QPushButton::clicked, this, &ToolsPage::addTool);
    connect(m_remove, &QPushButton::clicked, this, &ToolsPage::removeSelectedTools);
    connect(m_undo, &QPushButton::clicked, undo, &QUndoStack::undo);
    connect(m_redo, &QPushButton::clicked, undo, &QUndoStack::redo);
    connect(m_import, &QPushButton::clicked, this, &ToolsPage::importCsv);
    connect(m_export, &QPushButton::clicked, this, &ToolsPage::exportCsv);
    connect(m_discard, &QPushButton::clicked, this, &ToolsPage::discardChanges);
    connect(m_apply, &QPushButton::clicked, this, &ToolsPage::applyChanges);
    connect(m_addMaterial, &QPushButton::clicked, this, &ToolsPage::addMaterial);
    connect(m_removeMaterial, &QPushButton::clicked, this, &ToolsPage::removeSelectedMaterial);
    connect(undo, &QUndoStack::canUndoChanged, this, &ToolsPage::updateState);
    connect(undo, &QUndoStack::canRedoChanged, this, &ToolsPage::updateState);
    auto* undoAction = undo->createUndoAction(this);
    undoAction->setShortcut(QKeySequence::Undo);
    undoAction->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    auto* redoAction = undo->createRedoAction(this);
    redoAction->setShortcut(QKeySequence::Redo);
    redoAction->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    addAction(undoAction);
    addAction(redoAction);
}

void ToolsPage::buildImportPreview() {
    m_importTitle = new QLabel(m_preview);
    m_importTitle->setObjectName(QStringLiteral("SectionTitle"));
    m_importSummary = new QLabel(m_preview);
    m_importSummary->setObjectName(QStringLiteral("importSummary"));
    m_importSummary->setWordWrap(true);
    m_importView = tableView(m_preview, "importTable");
    m_importView->setModel(m_importModel);
    m_importView->setEditTriggers(QAbstractItemView::AllEditTriggers);
    m_importView->horizontalHeader()->setStretchLastSection(true);
    m_importView->verticalHeader()->setVisible(false);
    m_importView->setItemDelegate(new ChoiceDelegate(
        {ToolImportModel::Action},
        [](const QModelIndex&) {
            return QList<QPair<QString, QString>>{
                qMakePair(ToolImportModel::choiceText(ToolImportModel::Choice::KeepTable), QStringLiteral("table")),
                qMakePair(ToolImportModel::choiceText(ToolImportModel::Choice::TakeFile), QStringLiteral("file"))};
        },
        m_importView));
    m_takeAll = button(m_preview, "importTakeAll");
    m_keepAll = button(m_preview, "importKeepAll");
    m_importConfirm = button(m_preview, "importConfirm", "primary");
    m_importCancel = button(m_preview, "importCancel");
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_takeAll);
    buttons->addWidget(m_keepAll);
    buttons->addStretch(1);
    buttons->addWidget(m_importCancel);
    buttons->addWidget(m_importConfirm);
    auto* layout = new QVBoxLayout(m_preview);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_importTitle);
    layout->addWidget(m_importSummary);
    layout->addWidget(m_importView, 1);
    layout->addLayout(buttons);
    connect(m_takeAll, &QPushButton::clicked, this,
            [this] { m_importModel->setAllConflicts(ToolImportModel::Choice::TakeFile); });
    connect(m_keepAll, &QPushButton::clicked, this,
            [this] { m_importModel->setAllConflicts(ToolImportModel::Choice::KeepTable); });
    connect(m_importConfirm, &QPushButton::clicked, this, &ToolsPage::confirmImport);
    connect(m_importCancel, &QPushButton::clicked, this, &ToolsPage::cancelImport);
}

void ToolsPage::openStore() {
    m_store = context().data().tools();
    if (!m_store) {
        m_storeError = context().data().problem();
        m_stack->setCurrentWidget(m_storageProblem);
        return;
    }
    reloadFromStore();
    m_stack->setCurrentWidget(m_editor);
}

void ToolsPage::reloadFromStore() {
    if (!m_store) return;
    const std::vector<core::Material> materials = m_store->materials();
    m_model->load(m_store->tools(), materials);
    m_materialsModel->setMaterials(materials);
    m_auditModel->setEntries(m_store->audit());
    m_table->resizeColumnsToContents();
    m_auditView->resizeColumnsToContents();
    m_materialsView->resizeColumnsToContents();
}

QString ToolsPage::operatorName() const {
    const AppContext& c = context();
    return c.state ? c.state->operatorName().trimmed() : QString();
}

bool ToolsPage::requireOperator(const QString& action) {
    if (!operatorName().isEmpty()) return true;
    if (context().prompt)
        context().prompt->warn(this, action,
                               tr("Enter your name on the Settings page first: every applied change is recorded "
                                  "with it."));
    showStatus(tr("%1: no operator name (Settings)").arg(action), true);
    return false;
}

void ToolsPage::showStatus(const QString& text, bool problem) {
    m_lastStatus = text;
    m_lastStatusIsProblem = problem;
    m_lastStatusIsHint = false;
    m_status->setText(text);
    m_status->setStyleSheet(problem ? QStringLiteral("color: #b71c1c; font-weight: bold;") : QString());
}

QString ToolsPage::statusText() const {
    return m_status->text();
}

bool ToolsPage::previewShown() const {
    return m_stack->currentWidget() == m_preview;
}

void ToolsPage::updateState() {
    const int pending = m_model->pendingCount();
    const QStringList problems = m_model->problems();
    QUndoStack* undo = m_model->undoStack();
    m_undo->setEnabled(undo->canUndo());
    m_redo->setEnabled(undo->canRedo());
    m_undo->setToolTip(undo->canUndo() ? tr("Undo: %1").arg(undo->undoText()) : QString());
    m_redo->setToolTip(undo->canRedo() ? tr("Redo: %1").arg(undo->redoText()) : QString());
    m_apply->setEnabled(m_store && pending > 0 && problems.isEmpty());
    m_discard->setEnabled(pending > 0);
    const bool storeReady = m_store != nullptr;
    for (QPushButton* b : {m_add, m_remove, m_import, m_export, m_addMaterial, m_removeMaterial})
        b->setEnabled(storeReady);
    if (!problems.isEmpty())
        showStatus(tr("Fix before applying: %1").arg(problems.join(QStringLiteral("; "))), true);
    else if (pending > 0)
        showStatus(tr("Changed tools: %1 (highlighted). They are not stored until you apply them.").arg(pending));
    else if (m_lastStatusIsProblem || m_lastStatus.isEmpty() || m_lastStatusIsHint) {
        showStatus(tr("All changes are applied. Double-click a cell to edit it."));
        m_lastStatusIsHint = true;
    }
}

void ToolsPage::addTool() {
    const int row = m_model->addTool();
    const QModelIndex id = m_model->index(row, ToolTableModel::Id);
    m_tabs->setCurrentIndex(0);
    m_table->scrollTo(id);
    m_table->setCurrentIndex(id);
}

void ToolsPage::removeSelectedTools() {
    std::set<int> rows;
    for (const QModelIndex& index : m_table->selectionModel()->selectedIndexes())
        rows.insert(index.row());
    if (rows.empty() && m_table->currentIndex().isValid()) rows.insert(m_table->currentIndex().row());
    if (rows.empty()) {
        showStatus(tr("Select the tools to remove first."), true);
        return;
    }
    m_model->removeTools(QList<int>(rows.begin(), rows.end()));
}

QString ToolsPage::unappliedEdits() const {
    const int pending = m_model ? m_model->pendingCount() : 0;
    return pending > 0 ? tr("%n changed tool(s) on the Tools page", nullptr, pending) : QString();
}

bool ToolsPage::applyChanges() {
    if (!m_store) return false;
    if (!m_model->hasPending()) {
        showStatus(tr("Nothing to apply."));
        return true;
    }
    const QStringList problems = m_model->problems();
    if (!problems.isEmpty()) {
        if (context().prompt)
            context().prompt->warn(this, tr("Apply changes"),
                                   tr("These rows need fixing first:\n%1").arg(problems.join(QLatin1Char('\n'))));
        return false;
    }
    if (!requireOperator(tr("Apply changes"))) return false;
    try {
        const std::vector<storage::ToolAuditEntry> entries = m_store->apply(m_model->pendingEdits(), operatorName());
        reloadFromStore();
        showStatus(tr("Applied. Audit entries written with your name: %1.").arg(entries.size()));
        return true;
    } catch (const std::exception& e) {
        if (context().prompt)
            context().prompt->warn(
                this, tr("Apply changes"),
                tr("Nothing was stored: %1\nYour edits are still here.").arg(QString::fromStdString(e.what())));
        showStatus(tr("Not stored: %1").arg(QString::fromStdString(e.what())), true);
        return false;
    }
}

void ToolsPage::discardChanges() {
    const int pending = m_model->pendingCount();
    if (pending == 0) return;
    if (context().prompt &&
        context().prompt->ask(
            this, tr("Discard changes"),
            tr("Discard the pending changes of %1 tools? The stored table stays as it is.").arg(pending)) !=
            Prompt::Answer::Yes)
        return;
    m_model->discard();
    showStatus(tr("Pending changes discarded."));
}

void ToolsPage::importCsv() {
    if (!context().prompt) return;
    const QString path = context().prompt->openFileName(this, tr("Import tools"), tr("CSV files (*.csv)"));
    if (!path.isEmpty()) previewImport(path);
}

bool ToolsPage::previewImport(const QString& path) {
    QFile file(path);
    std::vector<core::ToolCsvRow> rows;
    try {
        if (!file.open(QIODevice::ReadOnly)) throw std::invalid_argument(file.errorString().toStdString());
        const QByteArray bytes = file.readAll();
        rows = core::parseToolCsv(std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
    } catch (const std::invalid_argument& e) {
        const QString why =
            tr("%1 cannot be imported: %2").arg(QFileInfo(path).fileName(), QString::fromStdString(e.what()));
        if (context().prompt) context().prompt->warn(this, tr("Import tools"), why);
        showStatus(why, true);
        return false;
    }
    m_importFile = QFileInfo(path).fileName();
    m_importModel->setRows(rows, *m_model);
    m_importView->resizeColumnsToContents();
    m_importView->horizontalHeader()->resizeSection(
        ToolImportModel::Details,
        std::min(m_importView->horizontalHeader()->sectionSize(ToolImportModel::Details), 700));
    retranslate();
    m_stack->setCurrentWidget(m_preview);
    return true;
}

void ToolsPage::confirmImport() {
    const std::vector<core::ToolRecord> tools = m_importModel->toImport();
    m_model->importTools(tools, tr("Import %1").arg(m_importFile));
    m_stack->setCurrentWidget(m_editor);
    m_tabs->setCurrentIndex(0);
    m_table->resizeColumnsToContents();
    showStatus(tr("Tools imported from %1: %2, highlighted until you apply them.").arg(m_importFile).arg(tools.size()));
}

void ToolsPage::cancelImport() {
    m_stack->setCurrentWidget(m_editor);
    showStatus(tr("Import cancelled; the table is unchanged."));
}

void ToolsPage::exportCsv() {
    if (!context().prompt) return;
    const QString path =
        context().prompt->saveFileName(this, tr("Export tools"), QStringLiteral("tools.csv"), tr("CSV files (*.csv)"));
    if (path.isEmpty()) return;
    const std::vector<core::ToolRecord> tools = m_model->currentTools();
    const QByteArray bytes = QByteArray::fromStdString(core::toolsToCsv(tools));
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(bytes) != bytes.size() || !file.flush()) {
        const QString why = tr("Cannot write %1: %2").arg(path, file.errorString());
        context().prompt->warn(this, tr("Export tools"), why);
        showStatus(why, true);
        return;
    }
    const int pending = m_model->pendingCount();
    showStatus(pending > 0 ? tr("Exported %1 tools to %2, including %3 change(s) not applied yet.")
                                 .arg(tools.size())
                                 .arg(QFileInfo(path).fileName())
                                 .arg(pending)
                           : tr("Exported %1 tools to %2.").arg(tools.size()).arg(QFileInfo(path).fileName()));
}

void ToolsPage::addMaterial() {
    if (!m_store || !requireOperator(tr("Add material"))) return;
    QString name;
    for (int n = 1;; ++n) {
        name = tr("New material %1").arg(n);
        bool used = false;
        for (const core::Material& m : m_materialsModel->materials())
            used = used || QString::fromStdString(m.name) == name;
        if (!used) break;
    }
    try {
        m_store->saveMaterial({name.toStdString(), 210'000.0}, operatorName());
        const std::vector<core::Material> materials = m_store->materials();
        m_materialsModel->setMaterials(materials);
        m_materialsView->resizeColumnsToContents();
        m_model->setMaterials(materials);
        m_auditModel->setEntries(m_store->audit());
        showStatus(tr("Added %1 (E 210000 MPa): double-click to rename it and set E.").arg(name));
    } catch (const std::exception& e) {
        showStatus(tr("Not stored: %1").arg(QString::fromStdString(e.what())), true);
    }
}

void ToolsPage::removeSelectedMaterial() {
    if (!m_store) return;
    const QModelIndex current = m_materialsView->currentIndex();
    if (!current.isValid()) {
        showStatus(tr("Select the material to remove first."), true);
        return;
    }
    if (!requireOperator(tr("Remove material"))) return;
    const std::string name = m_materialsModel->materials().at(static_cast<std::size_t>(current.row())).name;
    try {
        m_store->removeMaterial(name, operatorName());
        const std::vector<core::Material> materials = m_store->materials();
        m_materialsModel->setMaterials(materials);
        m_materialsView->resizeColumnsToContents();
        m_model->setMaterials(materials);
        m_auditModel->setEntries(m_store->audit());
        showStatus(tr("Removed %1; tools keep their stored E.").arg(QString::fromStdString(name)));
    } catch (const std::exception& e) {
        showStatus(tr("Not stored: %1").arg(QString::fromStdString(e.what())), true);
    }
}

void ToolsPage::onMaterialEdited(const QString& previousName, const core::Material& material) {
    if (!m_store || !requireOperator(tr("Edit material"))) return;
    try {
        if (previousName.toStdString() != material.name)
            m_store->removeMaterial(previousName.toStdString(), operatorName());
        m_store->saveMaterial(material, operatorName());
        const std::vector<core::Material> materials = m_store->materials();
        m_materialsModel->setMaterials(materials);
        m_materialsView->resizeColumnsToContents();
        m_model->setMaterials(materials);
        m_auditModel->setEntries(m_store->audit());
        showStatus(tr("%1: E %2 MPa stored; tools keep the E they have until you choose the material again.")
                       .arg(QString::fromStdString(material.name))
                       .arg(material.youngsModulusMpa, 0, 'f', 0));
    } catch (const std::exception& e) {
        showStatus(tr("Not stored: %1").arg(QString::fromStdString(e.what())), true);
    }
}

void ToolsPage::retranslate() {
    m_add->setText(tr("Add tool"));
    m_remove->setText(tr("Remove"));
    m_undo->setText(tr("Undo"));
    m_redo->setText(tr("Redo"));
    m_import->setText(tr("Import CSV…"));
    m_export->setText(tr("Export CSV…"));
    m_discard->setText(tr("Discard"));
    m_apply->setText(tr("Apply changes", "button"));
    m_addMaterial->setText(tr("Add material"));
    m_removeMaterial->setText(tr("Remove material"));
    m_materialsHint->setText(
        tr("Young's modulus of each holder material. Choosing a material for a tool copies its E; "
           "every change here is stored at once and recorded in the audit."));
    m_tabs->setTabText(0, tr("Tools"));
    m_tabs->setTabText(1, tr("Materials"));
    m_tabs->setTabText(2, tr("Audit"));
    m_takeAll->setText(tr("Take all from file"));
    m_keepAll->setText(tr("Keep all in table"));
    m_importConfirm->setText(tr("Import"));
    m_importCancel->setText(tr("Cancel"));
    m_importTitle->setText(tr("Import %1").arg(m_importFile));
    m_importSummary->setText(
        tr("%1 new, %2 different from the table, %3 the same, %4 cannot be read. Choose for each different tool "
           "whether to keep the table's values or take the file's; imported rows stay pending until you apply them.")
            .arg(m_importModel->count(ToolImportModel::State::New))
            .arg(m_importModel->count(ToolImportModel::State::Conflict))
            .arg(m_importModel->count(ToolImportModel::State::Unchanged))
            .arg(m_importModel->count(ToolImportModel::State::Invalid)));
    m_storageProblem->setTexts(tr("The tool table cannot be opened"),
                               tr("%1<br><br>The table is stored in the run history database; check the database "
                                  "on the Settings page.")
                                   .arg(m_storeError.toHtmlEscaped()));
    for (QTableView* view : {m_table, m_auditView, m_materialsView})
        view->resizeColumnsToContents();  // the headers are longer or shorter in the new language
    updateState();
}

}  // namespace tt::ui
