// The Tools page offscreen (issue 6, item 1): editing the tool table with validation, undo/redo,
// pending highlight, apply with audit, CSV import through the preview with conflicts, export.
#include "ui/pages/tools_page.h"

#include <gtest/gtest.h>

#include <QApplication>
#include <QFile>
#include <QLineEdit>
#include <QPushButton>
#include <QTabWidget>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include "core/storage/tool_store.h"
#include "screenshots.h"
#include "scripted_prompt.h"
#include "ui/app_state.h"
#include "ui/tools/materials_model.h"
#include "ui/tools/tool_audit_model.h"
#include "ui/tools/tool_import_model.h"
#include "ui/tools/tool_table_model.h"

namespace tt::ui {
namespace {

class ToolsPageTest : public ::testing::Test {
protected:
    void SetUp() override {
        state.setOperatorName(QStringLiteral("Anna Test"));
        context.databasePath = dir.filePath(QStringLiteral("history.sqlite"));
    }
    QString writeFile(const QString& name, const QByteArray& content) {
        const QString path = dir.filePath(name);
        QFile f(path);
        EXPECT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(content);
        return path;
    }
    static bool edit(ToolTableModel* m, int row, int column, const QString& text) {
        return m->setData(m->index(row, column), text, Qt::EditRole);
    }
    static QString cell(ToolTableModel* m, int row, int column) {
        return m->data(m->index(row, column), Qt::EditRole).toString();
    }

    QTemporaryDir dir;
    test::ScriptedPrompt prompt;
    AppState state;
    AppContext context{&prompt, &state, nullptr, QString()};
};

TEST_F(ToolsPageTest, EditsWithValidationUndoAndAppliesWithAudit) {
    ToolsPage page(context);
    page.resize(1400, 800);
    page.show();
    ToolTableModel* m = page.toolModel();
    ASSERT_EQ(m->rowCount(), 0);
    page.addTool();
    ASSERT_EQ(m->rowCount(), 1);
    EXPECT_EQ(cell(m, 0, ToolTableModel::Id), QStringLiteral("T1"));
    EXPECT_TRUE(m->data(m->index(0, ToolTableModel::Id), ToolTableModel::PendingRole).toBool());

    // A value that is not a number is refused with its unit; nothing changes.
    EXPECT_FALSE(edit(m, 0, ToolTableModel::Overhang, QStringLiteral("abc")));
    EXPECT_TRUE(page.statusText().contains(QStringLiteral("overhang l: 'abc' is not a number in mm")))
        << page.statusText().toStdString();
    EXPECT_EQ(cell(m, 0, ToolTableModel::Overhang), QStringLiteral("200"));

    // Typing into the real editor of the table view.
    QTableView* view = page.toolView();
    const QModelIndex overhang = m->index(0, ToolTableModel::Overhang);
    view->setCurrentIndex(overhang);
    view->edit(overhang);
    auto* editor = qobject_cast<QLineEdit*>(view->indexWidget(overhang) ? view->indexWidget(overhang)
                                                                        : QApplication::focusWidget());
    if (!editor) editor = view->viewport()->findChild<QLineEdit*>();
    ASSERT_NE(editor, nullptr);
    editor->selectAll();
    QTest::keyClicks(editor, QStringLiteral("400"));
    QTest::keyClick(editor, Qt::Key_Return);
    QApplication::processEvents();  // the delegate commits on Return through a queued call
    EXPECT_EQ(cell(m, 0, ToolTableModel::Overhang), QStringLiteral("400"));

    // Undo and redo.
    m->undoStack()->undo();
    EXPECT_EQ(cell(m, 0, ToolTableModel::Overhang), QStringLiteral("200"));
    m->undoStack()->redo();
    EXPECT_EQ(cell(m, 0, ToolTableModel::Overhang), QStringLiteral("400"));

    // An out-of-range diameter is accepted as typed but blocks Apply until fixed.
    EXPECT_TRUE(edit(m, 0, ToolTableModel::Diameter, QStringLiteral("2")));
    EXPECT_TRUE(m->data(m->index(0, ToolTableModel::Diameter), ToolTableModel::ProblemRole).toBool());
    EXPECT_FALSE(page.findChild<QPushButton*>(QStringLiteral("toolApply"))->isEnabled());
    EXPECT_FALSE(page.applyChanges());
    EXPECT_TRUE(prompt.lastText.contains(QStringLiteral("diameter d: 2 mm must be between 5 and 500 mm")))
        << prompt.lastText.toStdString();
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("tools_pending_with_problem")));

    EXPECT_TRUE(edit(m, 0, ToolTableModel::Diameter, QStringLiteral("40")));
    EXPECT_TRUE(edit(m, 0, ToolTableModel::Name, QStringLiteral("Boring bar D40 L400")));
    EXPECT_TRUE(edit(m, 0, ToolTableModel::CurrentToForceGain, QStringLiteral("150")));
    // k = 3 · 210000 · π 40⁴/64 / 400³ = 1237 N/mm, shown in the computed column.
    EXPECT_EQ(m->data(m->index(0, ToolTableModel::ComputedStiffness)).toString(), QStringLiteral("1237"));
    ASSERT_TRUE(page.applyChanges());
    EXPECT_EQ(m->pendingCount(), 0);
    EXPECT_FALSE(m->undoStack()->canUndo());
    EXPECT_FALSE(m->data(m->index(0, ToolTableModel::Id), ToolTableModel::PendingRole).toBool());
    const auto& audit = page.auditModel()->entries();
    ASSERT_FALSE(audit.empty());
    for (const storage::ToolAuditEntry& e : audit) {
        EXPECT_EQ(e.changedBy, QStringLiteral("Anna Test"));
        EXPECT_EQ(e.subject, QStringLiteral("T1"));
    }

    // A later change is audited with old and new values.
    EXPECT_TRUE(edit(m, 0, ToolTableModel::Overhang, QStringLiteral("450")));
    EXPECT_EQ(m->data(m->index(0, ToolTableModel::Overhang), Qt::ToolTipRole).toString(),
              QStringLiteral("Applied value: 400"));
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("tools_pending_edit")));
    ASSERT_TRUE(page.applyChanges());
    const storage::ToolAuditEntry& last = page.auditModel()->entries().front();
    EXPECT_EQ(last.field, QStringLiteral("overhang_mm"));
    EXPECT_EQ(last.before, QStringLiteral("400"));
    EXPECT_EQ(last.after, QStringLiteral("450"));
    page.tabs()->setCurrentIndex(2);
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("tools_audit")));

    // Stored: a new page on the same database shows the applied table.
    ToolsPage again(context);
    ASSERT_EQ(again.toolModel()->rowCount(), 1);
    EXPECT_EQ(cell(again.toolModel(), 0, ToolTableModel::Overhang), QStringLiteral("450"));
}

TEST_F(ToolsPageTest, ImportsCsvThroughAPreviewWithConflicts) {
    ToolsPage page(context);
    page.resize(1400, 800);
    page.show();
    ToolTableModel* m = page.toolModel();
    page.addTool();  // T1
    page.addTool();  // T2
    edit(m, 0, ToolTableModel::CurrentToForceGain, QStringLiteral("150"));
    ASSERT_TRUE(page.applyChanges());

    const QString csv = writeFile(QStringLiteral("tools.csv"),
                                  "id,name,section,diameter_mm,overhang_mm,kp_n_per_a\n"
                                  "T1,Bar T1,round,40,200,150\n"          // same as the table (except the name)
                                  "T2,Bar T2,round,50,500,100\n"          // differs
                                  "T7,\"Bar, heavy\",round,80,800,150\n"  // new
                                  "T8,Broken,round,80,zero,150\n");       // cannot be read
    prompt.fileNames.push_back(csv);
    page.importCsv();
    ASSERT_TRUE(page.previewShown());
    ToolImportModel* preview = page.importModel();
    ASSERT_EQ(preview->rowCount(), 4);
    EXPECT_EQ(preview->count(ToolImportModel::State::New), 1);
    EXPECT_EQ(preview->count(ToolImportModel::State::Conflict), 2);  // T1's name, T2's size
    EXPECT_EQ(preview->count(ToolImportModel::State::Invalid), 1);
    EXPECT_TRUE(
        preview->row(3).details.join(QString()).contains(QStringLiteral("overhang l: 'zero' is not a number in mm")));
    EXPECT_TRUE(preview->row(1).details.contains(QStringLiteral("overhang_mm: 200 → 500")));
    // Take T2 from the file, keep T1 as it is in the table.
    ASSERT_TRUE(preview->setData(preview->index(1, ToolImportModel::Action), QStringLiteral("file")));
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("tools_import_preview")));
    page.confirmImport();
    EXPECT_FALSE(page.previewShown());
    ASSERT_EQ(m->rowCount(), 3);
    EXPECT_EQ(cell(m, 0, ToolTableModel::Name), QString());  // kept
    EXPECT_EQ(cell(m, 1, ToolTableModel::Overhang), QStringLiteral("500"));
    EXPECT_EQ(cell(m, 2, ToolTableModel::Name), QStringLiteral("Bar, heavy"));
    EXPECT_EQ(m->pendingCount(), 2);
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("tools_after_import")));

    // The import is one undo step.
    m->undoStack()->undo();
    EXPECT_EQ(m->rowCount(), 2);
    EXPECT_EQ(cell(m, 1, ToolTableModel::Overhang), QStringLiteral("200"));
    m->undoStack()->redo();
    EXPECT_EQ(m->rowCount(), 3);
    ASSERT_TRUE(page.applyChanges());

    // Cancel leaves the table alone; a file without an id column is refused with the reason.
    ASSERT_TRUE(page.previewImport(csv));
    page.cancelImport();
    EXPECT_EQ(m->pendingCount(), 0);
    EXPECT_FALSE(page.previewImport(writeFile(QStringLiteral("bad.csv"), "name,colour\nx,red\n")));
    EXPECT_TRUE(prompt.lastText.contains(QStringLiteral("unknown column 'colour'"))) << prompt.lastText.toStdString();
}

TEST_F(ToolsPageTest, ExportsTheTableAndRemovesWithUndo) {
    ToolsPage page(context);
    ToolTableModel* m = page.toolModel();
    page.addTool();
    page.addTool();
    ASSERT_TRUE(page.applyChanges());
    m->removeTools({1});
    EXPECT_TRUE(m->toolRow(1).removed);
    EXPECT_EQ(m->pendingCount(), 1);
    EXPECT_TRUE(m->data(m->index(1, ToolTableModel::Id), Qt::FontRole).value<QFont>().strikeOut());
    const QString out = dir.filePath(QStringLiteral("export.csv"));
    prompt.fileNames.push_back(out);
    page.exportCsv();
    QFile f(out);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
    ASSERT_EQ(lines.size(), 2);  // header + T1 (T2 is removed in the table as shown)
    EXPECT_TRUE(lines[0].startsWith("id,name,section,diameter_mm"));
    EXPECT_TRUE(page.statusText().contains(QStringLiteral("not applied yet")));
    m->undoStack()->undo();
    EXPECT_EQ(m->pendingCount(), 0);
}

TEST_F(ToolsPageTest, RefusesToApplyWithoutAnOperatorAndKeepsTheEdits) {
    state.setOperatorName(QString());
    ToolsPage page(context);
    page.addTool();
    EXPECT_FALSE(page.applyChanges());
    EXPECT_TRUE(prompt.log.contains(QStringLiteral("warn: Apply changes")));
    EXPECT_TRUE(prompt.lastText.contains(QStringLiteral("Settings page")));
    EXPECT_EQ(page.toolModel()->pendingCount(), 1);
}

TEST_F(ToolsPageTest, DiscardAsksFirst) {
    ToolsPage page(context);
    page.addTool();
    prompt.answers.push_back(Prompt::Answer::No);
    page.discardChanges();
    EXPECT_EQ(page.toolModel()->rowCount(), 1);
    prompt.answers.push_back(Prompt::Answer::Yes);
    page.discardChanges();
    EXPECT_EQ(page.toolModel()->rowCount(), 0);
}

TEST_F(ToolsPageTest, MaterialsSetTheModulusAndAreAudited) {
    ToolsPage page(context);
    page.resize(1400, 800);
    ToolTableModel* m = page.toolModel();
    page.addTool();
    ASSERT_TRUE(edit(m, 0, ToolTableModel::Material, QStringLiteral("Cemented carbide")));
    EXPECT_EQ(cell(m, 0, ToolTableModel::YoungsModulus), QStringLiteral("600000"));
    EXPECT_FALSE(edit(m, 0, ToolTableModel::Material, QStringLiteral("Cheese")));
    EXPECT_TRUE(page.statusText().contains(QStringLiteral("not in the materials list")));
    MaterialsModel* materials = page.materialsModel();
    int steel = -1;
    for (int i = 0; i < materials->rowCount(); ++i)
        if (materials->data(materials->index(i, 0)).toString() == QStringLiteral("Steel")) steel = i;
    ASSERT_GE(steel, 0);
    EXPECT_FALSE(materials->setData(materials->index(steel, MaterialsModel::Modulus), QStringLiteral("12")));
    EXPECT_TRUE(materials->setData(materials->index(steel, MaterialsModel::Modulus), QStringLiteral("205000")));
    EXPECT_EQ(page.auditModel()->entries().front().subject, QStringLiteral("material Steel"));
    EXPECT_EQ(page.auditModel()->entries().front().after, QStringLiteral("205000"));
    ASSERT_TRUE(edit(m, 0, ToolTableModel::Material, QStringLiteral("Steel")));
    EXPECT_EQ(cell(m, 0, ToolTableModel::YoungsModulus), QStringLiteral("205000"));
    page.tabs()->setCurrentIndex(1);
    page.show();
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("tools_materials")));
}

TEST_F(ToolsPageTest, SaysSoWhenTheDatabaseCannotBeOpened) {
    context.databasePath = dir.filePath(QStringLiteral("no/such/folder/x.sqlite"));
    QFile blocker(dir.filePath(QStringLiteral("no")));  // a file where a folder is needed
    ASSERT_TRUE(blocker.open(QIODevice::WriteOnly));
    blocker.close();
    ToolsPage page(context);
    page.resize(1000, 600);
    EXPECT_FALSE(page.findChild<QPushButton*>(QStringLiteral("toolAdd"))->isEnabled());
    EXPECT_TRUE(test::saveScreenshot(page, QStringLiteral("tools_no_database")));
}

}  // namespace
}  // namespace tt::ui
