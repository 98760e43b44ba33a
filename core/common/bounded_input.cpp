#include "core/common/bounded_input.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>

namespace tt::core {

namespace {

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};

std::invalid_argument cannotRead(int error) {
    return std::invalid_argument(std::string("cannot read: ") + std::strerror(error));
}

}  // namespace

std::string readBoundedFile(const std::string& path, const InputLimits& limits) {
    errno = 0;
    const std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
    if (!file) throw cannotRead(errno);
    std::string text;
    char buffer[65536];
    while (true) {
        const std::size_t got = std::fread(buffer, 1, sizeof buffer, file.get());
        if (got > 0) {
            if (text.size() + got > limits.maxBytes)
                throw std::invalid_argument("is larger than the limit of " + std::to_string(limits.maxBytes) +
                                            " bytes");
            text.append(buffer, got);
        }
        if (got < sizeof buffer) {
            if (std::ferror(file.get())) throw cannotRead(errno != 0 ? errno : EIO);
            break;
        }
    }
    checkTextLimits(text, limits);
    return text;
}

void checkTextLimits(std::string_view text, const InputLimits& limits) {
    std::size_t line = 0;
    std::size_t pos = 0;
    while (pos < text.size()) {
        ++line;
        if (limits.maxLines > 0 && line > limits.maxLines)
            throw std::invalid_argument("has more than " + std::to_string(limits.maxLines) + " lines (the limit)");
        const std::size_t end = std::min(text.find('\n', pos), text.size());
        if (limits.maxLineLength > 0 && end - pos > limits.maxLineLength)
            throw std::invalid_argument("line " + std::to_string(line) + " is longer than " +
                                        std::to_string(limits.maxLineLength) + " characters (the limit)");
        pos = end + 1;
    }
}

}  // namespace tt::core
