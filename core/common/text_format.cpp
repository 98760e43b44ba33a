#include "core/common/text_format.h"

#include <cstdio>

namespace tt::core {

namespace {

std::string printed(const char* format, int precision, double value) {
    const int length = std::snprintf(nullptr, 0, format, precision, value);
    std::string text(static_cast<std::size_t>(length), '\0');
    std::snprintf(text.data(), text.size() + 1, format, precision, value);
    return text;
}

}  // namespace

std::string formatFixed(double value, int decimals) {
    return printed("%.*f", decimals, value);
}

std::string formatSignificant(double value, int digits) {
    return printed("%.*g", digits, value);
}

}  // namespace tt::core
