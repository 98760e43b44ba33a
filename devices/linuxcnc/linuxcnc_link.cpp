#include "devices/linuxcnc/linuxcnc_link.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>
#include <cerrno>
#include <chrono>
#include <cstring>

namespace tt::devices::linuxcnc {

namespace {

using Clock = std::chrono::steady_clock;

int remainingMs(Clock::time_point deadline) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    return left < 0 ? 0 : static_cast<int>(left);
}

std::string systemError(int code) {
    return std::strerror(code);
}

/// Connects `fd` to `address` within the deadline; 0 or the errno.
int connectWithin(int fd, const sockaddr* address, socklen_t length, Clock::time_point deadline) {
    const int flags = fcntl(fd, F_GETFL, 0);
    fcntl(fd, F_SETFL, flags | O_NONBLOCK);
    int result = ::connect(fd, address, length);
    if (result != 0 && errno != EINPROGRESS) return errno;
    if (result != 0) {
        pollfd p{fd, POLLOUT, 0};
        if (poll(&p, 1, remainingMs(deadline)) <= 0) return ETIMEDOUT;
        int error = 0;
        socklen_t size = sizeof error;
        getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &size);
        if (error != 0) return error;
    }
    fcntl(fd, F_SETFL, flags);
    return 0;
}

}  // namespace

LinuxCncLink::LinuxCncLink(Endpoint endpoint) : m_endpoint(std::move(endpoint)) {}

LinuxCncLink::~LinuxCncLink() {
    close();
}

void LinuxCncLink::connect(int timeoutMs) {
    close();
    const Clock::time_point deadline = Clock::now() + std::chrono::milliseconds(timeoutMs);
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    addrinfo* found = nullptr;
    const std::string port = std::to_string(m_endpoint.port);
    if (const int rc = getaddrinfo(m_endpoint.host.c_str(), port.c_str(), &hints, &found); rc != 0)
        throw LinuxCncError(FailureKind::Unreachable,
                            "LinuxCNC at " + m_endpoint.text() + ": the host is unknown (" + gai_strerror(rc) + ")");
    int lastError = ECONNREFUSED;
    for (addrinfo* a = found; a != nullptr && m_fd < 0; a = a->ai_next) {
        const int fd = ::socket(a->ai_family, a->ai_socktype | SOCK_CLOEXEC, a->ai_protocol);
        if (fd < 0) {
            lastError = errno;
            continue;
        }
        lastError = connectWithin(fd, a->ai_addr, a->ai_addrlen, deadline);
        if (lastError == 0) {
            const int one = 1;
            setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
            m_fd = fd;
        } else {
            ::close(fd);
        }
    }
    freeaddrinfo(found);
    if (m_fd < 0)
        throw LinuxCncError(FailureKind::Unreachable,
                            "LinuxCNC at " + m_endpoint.text() + " does not answer (" + systemError(lastError) + ")");
    m_framer.reset();
    m_lines.clear();
}

void LinuxCncLink::close() {
    if (m_fd >= 0) ::close(m_fd);
    m_fd = -1;
    m_framer.reset();
    m_lines.clear();
}

void LinuxCncLink::fail(FailureKind kind, const std::string& message) {
    close();
    throw LinuxCncError(kind, message);
}

void LinuxCncLink::send(const std::string& request) {
    if (m_fd < 0) fail(FailureKind::Lost, "LinuxCNC at " + m_endpoint.text() + " is not connected");
    // Replies left over from an earlier request mean the stream is out of step.
    if (!m_lines.empty())
        fail(FailureKind::Garbage, "LinuxCNC at " + m_endpoint.text() + " sent '" + m_lines.front() +
                                       "' that answers no request (the replies are out of step)");
    const std::string line = request + "\r\n";
    std::size_t sent = 0;
    while (sent < line.size()) {
        const ssize_t n = ::send(m_fd, line.data() + sent, line.size() - sent, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0)
            fail(FailureKind::Lost,
                 "LinuxCNC at " + m_endpoint.text() + ": the connection was lost (" + systemError(errno) + ")");
        sent += static_cast<std::size_t>(n);
    }
}

std::string LinuxCncLink::nextLine(const std::string& request, int timeoutMs) {
    const Clock::time_point deadline = Clock::now() + std::chrono::milliseconds(timeoutMs);
    char buffer[4096];
    while (m_lines.empty()) {
        pollfd p{m_fd, POLLIN, 0};
        const int ready = poll(&p, 1, remainingMs(deadline));
        if (ready < 0 && errno == EINTR) continue;
        if (ready == 0)
            fail(FailureKind::Timeout, "LinuxCNC at " + m_endpoint.text() + " did not answer '" + request +
                                           "' within " + std::to_string(timeoutMs) + " ms");
        const ssize_t n = ::recv(m_fd, buffer, sizeof buffer, 0);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const std::string cut = m_framer.pending() > 0 ? " in the middle of a reply" : "";
            fail(FailureKind::Lost, "LinuxCNC at " + m_endpoint.text() + " closed the connection" + cut +
                                        " while answering '" + request + "'");
        }
        for (std::string& line : m_framer.feed(std::string_view(buffer, static_cast<std::size_t>(n))))
            m_lines.push_back(std::move(line));
        if (m_framer.corrupt())
            fail(FailureKind::Garbage,
                 "LinuxCNC at " + m_endpoint.text() + ": " + m_framer.problem() + " (answering '" + request + "')");
    }
    std::string line = std::move(m_lines.front());
    m_lines.pop_front();
    return line;
}

std::string LinuxCncLink::requestLine(const std::string& request, int timeoutMs) {
    send(request);
    std::string line = nextLine(request, timeoutMs);
    ++m_requests;
    return line;
}

Reply LinuxCncLink::request(const std::string& request, int timeoutMs) {
    const std::string line = requestLine(request, timeoutMs);
    ParseResult<Reply> reply = replyTo(request, line);
    if (!reply) fail(FailureKind::Garbage, "LinuxCNC at " + m_endpoint.text() + ": " + reply.error());
    return reply.value();
}

}  // namespace tt::devices::linuxcnc
