#pragma once

#include <cstdint>
#include <deque>
#include <stdexcept>
#include <string>

#include "devices/parsers/linuxcnc_reply.h"

namespace tt::devices::linuxcnc {

/// Why talking to LinuxCNC failed.
enum class FailureKind {
    Unreachable,  ///< no connection (refused, no route, name unknown)
    Lost,         ///< the connection ended, possibly in the middle of a reply
    Timeout,      ///< no reply within the time allowed
    Garbage,      ///< a reply the parser refused (corrupt, cut off or out of step)
    Refused,      ///< LinuxCNC answered NAK, or is not in a state to do it (E-stop, not homed, running)
    Differs,      ///< a value read back is not the one written
};

/// A failure with its kind and the message in the user's terms (it names the host and what failed).
class LinuxCncError : public std::runtime_error {
public:
    LinuxCncError(FailureKind kind, const std::string& message) : std::runtime_error(message), m_kind(kind) {}
    FailureKind kind() const { return m_kind; }
    /// Whether the connection is unusable after it (it was reset).
    bool connectionReset() const {
        return m_kind == FailureKind::Unreachable || m_kind == FailureKind::Lost || m_kind == FailureKind::Timeout ||
               m_kind == FailureKind::Garbage;
    }

private:
    FailureKind m_kind;
};

/// Where LinuxCNC's remote shell listens.
struct Endpoint {
    std::string host = "127.0.0.1";
    int port = 5007;
    /// "127.0.0.1:5007", for messages.
    std::string text() const { return host + ":" + std::to_string(port); }
};

/// One TCP connection to linuxcncrsh, request by request: a request is sent only when the previous one is
/// answered (the shell parses commands with a non-reentrant tokenizer, so two requests at once on two
/// connections can corrupt each other). Blocking with timeouts (POSIX sockets and poll); use it from one
/// thread. Every failure throws LinuxCncError and, except Refused, closes the connection: the replies
/// would be out of step.
class LinuxCncLink {
public:
    explicit LinuxCncLink(Endpoint endpoint);
    ~LinuxCncLink();
    LinuxCncLink(const LinuxCncLink&) = delete;
    LinuxCncLink& operator=(const LinuxCncLink&) = delete;

    /// Connects within `timeoutMs`. Throws LinuxCncError (Unreachable).
    void connect(int timeoutMs);
    /// Closes the connection (nothing when closed).
    void close();
    bool connected() const { return m_fd >= 0; }

    /// Sends `request` and returns its reply (replyTo), waiting at most `timeoutMs`. Throws LinuxCncError:
    /// Lost, Timeout or Garbage (and closes the connection).
    Reply request(const std::string& request, int timeoutMs);
    /// Sends `request` and returns the next line as it is (the shell's echo of a command). Throws as request().
    std::string requestLine(const std::string& request, int timeoutMs);

    const Endpoint& endpoint() const { return m_endpoint; }
    /// Requests answered on this link since it was made.
    std::uint64_t requests() const { return m_requests; }

private:
    void send(const std::string& request);
    std::string nextLine(const std::string& request, int timeoutMs);
    [[noreturn]] void fail(FailureKind kind, const std::string& message);

    Endpoint m_endpoint;
    int m_fd = -1;
    ReplyFramer m_framer;
    std::deque<std::string> m_lines;
    std::uint64_t m_requests = 0;
};

}  // namespace tt::devices::linuxcnc
