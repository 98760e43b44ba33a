#pragma once

#include <QHash>
#include <QString>
#include <QWidget>
#include <array>

#include "core/sim/hydraulic/hydraulic_feed_params.h"
#include "ui/process/feed_block_diagram.h"

class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QPushButton;
class QStackedWidget;

namespace tt::ui {

/// The parameters of one block of the feed stabiliser at a time (the block chosen on the diagram), each in
/// a spin box with its unit and the limits core::validate() enforces, and below them what follows from
/// them (time constants, gains). Values are shown in workshop units (mm, mm/s, ms, MPa, µH) and kept in SI.
class FeedParameterForm : public QWidget {
    Q_OBJECT
public:
    explicit FeedParameterForm(QWidget* parent = nullptr);

    /// Shows `params` (without emitting changed()).
    void setParams(const core::HydraulicFeedParams& params);
    /// The values in the fields, SI.
    core::HydraulicFeedParams params() const;
    /// Shows the fields of `block`.
    void showBlock(FeedBlock block);
    /// The spin box of the parameter `key` ("spool.damping_ratio"), nullptr when unknown.
    QDoubleSpinBox* field(const QString& key) const;
    /// The amplifier's "Design gain" button.
    QPushButton* designButton() const { return m_design; }
    void retranslate();

signals:
    /// A value was edited.
    void changed();
    /// The user asks for the lap and gain that make up the current load's leakage.
    void designRequested();

private:
    void build();
    void refreshDerived();
    QString blockTitle(FeedBlock block) const;
    std::pair<QString, QString> labelAndUnit(const QString& key) const;

    QGroupBox* m_box;
    QStackedWidget* m_pages;
    QPushButton* m_design;
    QHash<QString, QDoubleSpinBox*> m_fields;
    QHash<QString, QLabel*> m_labels;
    std::array<QLabel*, kFeedBlockCount> m_derived{};
    FeedBlock m_block = FeedBlock::Spool;
};

}  // namespace tt::ui
