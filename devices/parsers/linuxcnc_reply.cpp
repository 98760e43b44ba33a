#include "devices/parsers/linuxcnc_reply.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace tt::devices::linuxcnc {

namespace {

bool isTerminator(char c) {
    return c == '\r' || c == '\n';
}

bool printable(char c) {
    const auto u = static_cast<unsigned char>(c);
    return u >= 0x20 && u < 0x7f;
}

/// `text` with non-printable characters shown as \xNN, at most 40 characters (for messages).
std::string shown(std::string_view text) {
    std::string out;
    for (const char c : text.substr(0, 40)) {
        if (printable(c)) {
            out += c;
        } else {
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02X", static_cast<unsigned>(static_cast<unsigned char>(c)));
            out += hex;
        }
    }
    if (text.size() > 40) out += "...";
    return out;
}

/// `text` shown between single quotes.
std::string quoted(std::string_view text) {
    std::string out(1, '\'');
    out += shown(text);
    out += '\'';
    return out;
}

std::string upper(std::string_view text) {
    std::string out(text);
    std::transform(out.begin(), out.end(), out.begin(), [](char c) { return c >= 'a' && c <= 'z' ? c - 32 : c; });
    return out;
}

std::vector<std::string> splitWords(std::string_view text) {
    std::vector<std::string> words;
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && text[i] == ' ')
            ++i;
        std::size_t j = i;
        while (j < text.size() && text[j] != ' ')
            ++j;
        if (j > i) words.emplace_back(text.substr(i, j - i));
        i = j;
    }
    return words;
}

bool validKey(std::string_view key) {
    if (key.empty() || key.size() > 40) return false;
    return std::all_of(key.begin(), key.end(),
                       [](char c) { return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'; });
}

template <typename T>
ParseResult<T> refuse(const std::string& why) {
    return ParseResult<T>::failure(why);
}

/// The reply of kind Value with key `key`, or why not.
std::string expectValue(const Reply& reply, std::string_view key) {
    if (reply.kind != ReplyKind::Value) return "expected a value of " + std::string(key) + ", got an acknowledgement";
    if (reply.key != key) return "expected " + std::string(key) + ", got " + reply.key;
    return {};
}

/// The single word of a value reply of `key`, or why not.
std::string singleWord(const Reply& reply, std::string_view key, std::string& word) {
    if (std::string why = expectValue(reply, key); !why.empty()) return why;
    if (reply.words.size() != 1)
        return std::string(key) + " has " + std::to_string(reply.words.size()) + " words, expected 1";
    word = reply.words.front();
    return {};
}

}  // namespace

// ---- framing --------------------------------------------------------------------------------------------

ReplyFramer::ReplyFramer(std::size_t maxLength) : m_maxLength(maxLength == 0 ? 1 : maxLength) {}

std::vector<std::string> ReplyFramer::feed(std::string_view bytes) {
    std::vector<std::string> lines;
    for (const char c : bytes) {
        if (m_corrupt) break;
        if (isTerminator(c)) {
            if (!m_buffer.empty()) lines.push_back(std::move(m_buffer));
            m_buffer.clear();
            continue;
        }
        if (!printable(c)) {
            m_corrupt = true;
            m_problem = "a reply holds a byte that is not printable text (after '" + shown(m_buffer) + "')";
            break;
        }
        if (m_buffer.size() >= m_maxLength) {
            m_corrupt = true;
            m_problem =
                "a reply is longer than " + std::to_string(m_maxLength) + " characters ('" + shown(m_buffer) + "')";
            break;
        }
        m_buffer += c;
    }
    return lines;
}

void ReplyFramer::reset() {
    m_buffer.clear();
    m_corrupt = false;
    m_problem.clear();
}

// ---- replies --------------------------------------------------------------------------------------------

ParseResult<Reply> parseReply(std::string_view line) {
    if (line.empty()) return refuse<Reply>("an empty reply");
    if (line.size() > kMaxReplyLength) return refuse<Reply>("a reply longer than 512 characters");
    if (!std::all_of(line.begin(), line.end(), printable))
        return refuse<Reply>("the reply '" + shown(line) + "' holds a byte that is not printable text");
    const std::vector<std::string> words = splitWords(line);
    if (words.empty()) return refuse<Reply>("a reply of spaces only");
    Reply r;
    if (words[0] == "HELLO") {
        r.key = "HELLO";
        if (words.size() == 2 && words[1] == "NAK") {
            r.kind = ReplyKind::HelloNak;
            return ParseResult<Reply>::success(std::move(r));
        }
        if (words.size() == 4 && words[1] == "ACK") {
            r.kind = ReplyKind::HelloAck;
            r.words = {words[2], words[3]};
            return ParseResult<Reply>::success(std::move(r));
        }
        return refuse<Reply>("the hello reply '" + shown(line) +
                             "' is neither HELLO ACK <server> <version> nor HELLO NAK");
    }
    if ((words[0] == "SET" || words[0] == "GET") && words.size() == 3 && (words[2] == "ACK" || words[2] == "NAK")) {
        if (!validKey(words[1])) return refuse<Reply>("the acknowledgement '" + shown(line) + "' names no command");
        if (words[0] == "GET" && words[2] == "ACK")
            return refuse<Reply>(quoted(line) + ": a get is never acknowledged");
        r.kind = words[2] == "ACK" ? ReplyKind::Ack : ReplyKind::Nak;
        r.key = words[1];
        return ParseResult<Reply>::success(std::move(r));
    }
    if (!validKey(words[0])) return refuse<Reply>("the reply '" + shown(line) + "' does not start with a key");
    r.kind = ReplyKind::Value;
    r.key = words[0];
    r.words.assign(words.begin() + 1, words.end());
    const std::size_t space = line.find(' ');
    if (space != std::string_view::npos) r.text = std::string(line.substr(space + 1));
    return ParseResult<Reply>::success(std::move(r));
}

ParseResult<Reply> replyTo(std::string_view request, std::string_view line) {
    ParseResult<Reply> parsed = parseReply(line);
    if (!parsed) return parsed;
    const Reply& r = parsed.value();
    const std::vector<std::string> words = splitWords(request);
    const std::string verb = words.empty() ? std::string() : upper(words[0]);
    const std::string command = words.size() > 1 ? upper(words[1]) : std::string();
    const std::string answer = quoted(line) + " does not answer '" + shown(request) + "'";
    if (verb == "HELLO") {
        if (r.kind == ReplyKind::HelloAck || r.kind == ReplyKind::HelloNak) return parsed;
        return refuse<Reply>(answer);
    }
    if (verb == "SET") {
        if ((r.kind == ReplyKind::Ack || r.kind == ReplyKind::Nak) && r.key == command) return parsed;
        return refuse<Reply>(answer);
    }
    if (verb == "GET") {
        std::string key = command;
        if (key == "PROGRAM_LINEAR_UNITS") key = "PROGRAM_UNITS";
        if (key == "TIMEOUT") key = "SET_TIMEOUT";
        if (r.kind == ReplyKind::Nak && r.key == command) return parsed;
        if (r.kind == ReplyKind::Value && r.key == key) return parsed;
        return refuse<Reply>(answer);
    }
    return refuse<Reply>(quoted(request) + " is not a request of the remote shell (hello, get, set)");
}

// ---- values ---------------------------------------------------------------------------------------------

ParseResult<double> number(std::string_view word) {
    if (word.empty() || word.size() > 40) return refuse<double>(quoted(word) + " is not a number");
    const char* first = word.data();
    const char* last = word.data() + word.size();
    if (*first == '+') ++first;
    double value = 0.0;
    const auto [end, ec] = std::from_chars(first, last, value, std::chars_format::fixed);
    if (ec != std::errc() || end != last || first == last) return refuse<double>(quoted(word) + " is not a number");
    if (!std::isfinite(value)) return refuse<double>(quoted(word) + " is not a finite number");
    return ParseResult<double>::success(value);
}

ParseResult<bool> onOff(const Reply& reply, std::string_view key) {
    std::string word;
    if (std::string why = singleWord(reply, key, word); !why.empty()) return refuse<bool>(why);
    if (word == "ON") return ParseResult<bool>::success(true);
    if (word == "OFF") return ParseResult<bool>::success(false);
    return refuse<bool>(std::string(key) + " is '" + shown(word) + "', expected ON or OFF");
}

ParseResult<TaskMode> taskMode(const Reply& reply) {
    std::string word;
    if (std::string why = singleWord(reply, "MODE", word); !why.empty()) return refuse<TaskMode>(why);
    if (word == "MANUAL") return ParseResult<TaskMode>::success(TaskMode::Manual);
    if (word == "AUTO") return ParseResult<TaskMode>::success(TaskMode::Auto);
    if (word == "MDI") return ParseResult<TaskMode>::success(TaskMode::Mdi);
    return refuse<TaskMode>("MODE is '" + shown(word) + "', expected MANUAL, AUTO or MDI");
}

ParseResult<ProgramStatus> programStatus(const Reply& reply) {
    std::string word;
    if (std::string why = singleWord(reply, "PROGRAM_STATUS", word); !why.empty()) return refuse<ProgramStatus>(why);
    if (word == "IDLE") return ParseResult<ProgramStatus>::success(ProgramStatus::Idle);
    if (word == "RUNNING") return ParseResult<ProgramStatus>::success(ProgramStatus::Running);
    if (word == "PAUSED") return ParseResult<ProgramStatus>::success(ProgramStatus::Paused);
    return refuse<ProgramStatus>("PROGRAM_STATUS is '" + shown(word) + "', expected IDLE, RUNNING or PAUSED");
}

ParseResult<std::vector<bool>> jointsHomed(const Reply& reply) {
    if (std::string why = expectValue(reply, "JOINT_HOMED"); !why.empty()) return refuse<std::vector<bool>>(why);
    if (reply.words.empty() || reply.words.size() > 16)
        return refuse<std::vector<bool>>("JOINT_HOMED has " + std::to_string(reply.words.size()) + " joints");
    std::vector<bool> homed;
    for (const std::string& w : reply.words) {
        if (w == "YES" || w == "HOMED")
            homed.push_back(true);
        else if (w == "NO" || w == "NOT")
            homed.push_back(false);
        else
            return refuse<std::vector<bool>>("JOINT_HOMED holds '" + shown(w) + "', expected YES or NO");
    }
    return ParseResult<std::vector<bool>>::success(std::move(homed));
}

ParseResult<std::array<double, 6>> position(const Reply& reply, std::string_view key) {
    using Result = ParseResult<std::array<double, 6>>;
    if (std::string why = expectValue(reply, key); !why.empty()) return Result::failure(why);
    if (reply.words.size() != 6)
        return Result::failure(std::string(key) + " has " + std::to_string(reply.words.size()) +
                               " numbers, expected 6 (X Y Z A B C): the reply is cut off or garbled");
    std::array<double, 6> values{};
    for (std::size_t i = 0; i < 6; ++i) {
        const ParseResult<double> v = number(reply.words[i]);
        if (!v) return Result::failure(std::string(key) + ": " + v.error());
        values[i] = v.value();
    }
    return Result::success(values);
}

ParseResult<LinearUnits> linearUnits(const Reply& reply, std::string_view key) {
    std::string word;
    if (std::string why = singleWord(reply, key, word); !why.empty()) return refuse<LinearUnits>(why);
    if (word == "INCH") return ParseResult<LinearUnits>::success(LinearUnits::Inch);
    if (word == "MM") return ParseResult<LinearUnits>::success(LinearUnits::Millimetre);
    if (word == "CM") return ParseResult<LinearUnits>::success(LinearUnits::Centimetre);
    if (word == "CUSTOM") return ParseResult<LinearUnits>::success(LinearUnits::Custom);
    return refuse<LinearUnits>(std::string(key) + " is '" + shown(word) + "', expected INCH, MM, CM or CUSTOM");
}

ParseResult<std::int64_t> integerValue(const Reply& reply, std::string_view key) {
    std::string word;
    if (std::string why = singleWord(reply, key, word); !why.empty()) return refuse<std::int64_t>(why);
    std::int64_t value = 0;
    const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (ec != std::errc() || end != word.data() + word.size())
        return refuse<std::int64_t>(std::string(key) + " is '" + shown(word) + "', not a whole number");
    return ParseResult<std::int64_t>::success(value);
}

ParseResult<std::string> message(const Reply& reply, std::string_view key) {
    if (std::string why = expectValue(reply, key); !why.empty()) return refuse<std::string>(why);
    if (reply.words.size() == 1 && reply.words.front() == "OK") return ParseResult<std::string>::success({});
    return ParseResult<std::string>::success(reply.text);
}

ParseResult<std::vector<double>> taggedNumbers(std::string_view text, std::string_view tag, std::size_t count) {
    using Result = ParseResult<std::vector<double>>;
    const std::vector<std::string> words = splitWords(text);
    if (words.empty() || words.front() != tag)
        return Result::failure("the message '" + shown(text) + "' is not the one tagged " + std::string(tag));
    if (words.size() != count + 1)
        return Result::failure("the message tagged " + std::string(tag) + " has " + std::to_string(words.size() - 1) +
                               " numbers, expected " + std::to_string(count));
    std::vector<double> values;
    for (std::size_t i = 1; i < words.size(); ++i) {
        const ParseResult<double> v = number(words[i]);
        if (!v) return Result::failure("the message tagged " + std::string(tag) + ": " + v.error());
        values.push_back(v.value());
    }
    return Result::success(std::move(values));
}

std::string_view modeName(TaskMode mode) {
    switch (mode) {
        case TaskMode::Manual:
            return "manual";
        case TaskMode::Auto:
            return "auto";
        case TaskMode::Mdi:
            return "MDI";
    }
    return "unknown";
}

std::string_view statusName(ProgramStatus status) {
    switch (status) {
        case ProgramStatus::Idle:
            return "idle";
        case ProgramStatus::Running:
            return "running";
        case ProgramStatus::Paused:
            return "paused";
    }
    return "unknown";
}

std::string_view unitsName(LinearUnits units) {
    switch (units) {
        case LinearUnits::Inch:
            return "inch";
        case LinearUnits::Millimetre:
            return "mm";
        case LinearUnits::Centimetre:
            return "cm";
        case LinearUnits::Custom:
            return "custom units";
    }
    return "unknown";
}

double millimetresPer(LinearUnits units) {
    switch (units) {
        case LinearUnits::Inch:
            return 25.4;
        case LinearUnits::Millimetre:
            return 1.0;
        case LinearUnits::Centimetre:
            return 10.0;
        case LinearUnits::Custom:
            return 0.0;
    }
    return 0.0;
}

}  // namespace tt::devices::linuxcnc
