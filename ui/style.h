#pragma once

class QApplication;

namespace tt::ui {

/// Applies the operator style: the built-in style sheet (:/style/trueturn.qss), Fusion as the
/// base style and a font readable from a metre away.
void applyOperatorStyle(QApplication& app);

}  // namespace tt::ui
