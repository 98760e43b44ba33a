#pragma once

#include <optional>
#include <string>
#include <utility>

namespace tt::devices {

/// Outcome of decoding bytes from an instrument: the value, or why the bytes were refused
/// (in the user's terms, e.g. "sign is 'x', expected '+' or '-'"). Malformed input is an
/// expected event on a serial line, so parsers return this instead of throwing.
template <typename T>
class ParseResult {
public:
    /// A successful decode.
    static ParseResult success(T value) {
        ParseResult r;
        r.m_value = std::move(value);
        return r;
    }
    /// A refused input with its reason.
    static ParseResult failure(std::string reason) {
        ParseResult r;
        r.m_error = std::move(reason);
        return r;
    }

    bool ok() const { return m_value.has_value(); }
    explicit operator bool() const { return ok(); }
    /// The decoded value; only valid when ok().
    const T& value() const { return *m_value; }
    const T* operator->() const { return &*m_value; }
    /// Why the input was refused; empty when ok().
    const std::string& error() const { return m_error; }

private:
    ParseResult() = default;
    std::optional<T> m_value;
    std::string m_error;
};

}  // namespace tt::devices
