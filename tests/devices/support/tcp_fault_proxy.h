#pragma once

// A TCP proxy on 127.0.0.1 between TrueTurn and LinuxCNC's remote shell that forwards every line and, when the
// test says so, changes one: a request rewritten on its way to LinuxCNC (LinuxCNC then really refuses it or
// really holds another value), a reply replaced by garbage, or the connection cut in the middle of a reply.
// POSIX sockets and a thread of its own, so it works with the blocking client under test.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cstring>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace tt::test {

class TcpFaultProxy {
public:
    /// What to do with a line: forward it (possibly changed), or cut the connection after sending `cutWith`.
    struct Action {
        std::string line;
        bool cut = false;
    };
    using Rule = std::function<std::optional<Action>(const std::string& line)>;

    TcpFaultProxy(std::string upstreamHost, int upstreamPort)
        : m_host(std::move(upstreamHost)), m_upstreamPort(upstreamPort) {
        m_listener = ::socket(AF_INET, SOCK_STREAM, 0);
        const int one = 1;
        setsockopt(m_listener, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
        sockaddr_in a{};
        a.sin_family = AF_INET;
        a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        a.sin_port = 0;
        ::bind(m_listener, reinterpret_cast<sockaddr*>(&a), sizeof a);
        ::listen(m_listener, 4);
        socklen_t size = sizeof a;
        getsockname(m_listener, reinterpret_cast<sockaddr*>(&a), &size);
        m_port = ntohs(a.sin_port);
        m_thread = std::thread([this] { serve(); });
    }
    ~TcpFaultProxy() {
        m_stop = true;
        m_thread.join();
        ::close(m_listener);
    }
    TcpFaultProxy(const TcpFaultProxy&) = delete;
    TcpFaultProxy& operator=(const TcpFaultProxy&) = delete;

    int port() const { return m_port; }
    /// Applied to every request line (without its line end); nullopt forwards it unchanged.
    void onRequest(Rule rule) {
        std::lock_guard lock(m_mutex);
        m_toServer = std::move(rule);
    }
    /// Applied to every reply line (without its line end); nullopt forwards it unchanged.
    void onReply(Rule rule) {
        std::lock_guard lock(m_mutex);
        m_toClient = std::move(rule);
    }
    void clearRules() {
        std::lock_guard lock(m_mutex);
        m_toServer = nullptr;
        m_toClient = nullptr;
    }
    /// Connections accepted so far.
    int connections() const { return m_connections; }

private:
    static bool sendAll(int fd, const std::string& bytes) {
        std::size_t sent = 0;
        while (sent < bytes.size()) {
            const ssize_t n = ::send(fd, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
            if (n <= 0) return false;
            sent += static_cast<std::size_t>(n);
        }
        return true;
    }

    int connectUpstream() const {
        const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
        sockaddr_in a{};
        a.sin_family = AF_INET;
        a.sin_port = htons(static_cast<std::uint16_t>(m_upstreamPort));
        inet_pton(AF_INET, m_host.c_str(), &a.sin_addr);
        if (::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
            ::close(fd);
            return -1;
        }
        return fd;
    }

    /// Moves complete lines of `buffer` to `to`, each through `rule`; false when the connection is to be cut.
    bool relay(std::string& buffer, int to, bool toServer) {
        for (;;) {
            const std::size_t end = buffer.find_first_of("\r\n");
            if (end == std::string::npos) return true;
            std::size_t next = end;
            while (next < buffer.size() && (buffer[next] == '\r' || buffer[next] == '\n'))
                ++next;
            const std::string line = buffer.substr(0, end);
            const std::string terminator = buffer.substr(end, next - end);
            buffer.erase(0, next);
            std::optional<Action> action;
            {
                std::lock_guard lock(m_mutex);
                const Rule& rule = toServer ? m_toServer : m_toClient;
                if (rule && !line.empty()) action = rule(line);
            }
            if (!action) {
                if (!sendAll(to, line + terminator)) return false;
                continue;
            }
            if (action->cut) {
                sendAll(to, action->line);
                return false;
            }
            if (!sendAll(to, action->line + terminator)) return false;
        }
    }

    void pipe(int client) {
        const int server = connectUpstream();
        if (server < 0) {
            ::close(client);
            return;
        }
        std::string fromClient, fromServer;
        char chunk[4096];
        bool open = true;
        while (open && !m_stop) {
            pollfd p[2] = {{client, POLLIN, 0}, {server, POLLIN, 0}};
            if (poll(p, 2, 50) <= 0) continue;
            for (int i = 0; i < 2 && open; ++i) {
                if (!(p[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
                const ssize_t n = ::recv(p[i].fd, chunk, sizeof chunk, 0);
                if (n <= 0) {
                    open = false;
                    break;
                }
                std::string& buffer = i == 0 ? fromClient : fromServer;
                buffer.append(chunk, static_cast<std::size_t>(n));
                open = relay(buffer, i == 0 ? server : client, i == 0);
            }
        }
        ::close(server);
        ::close(client);
    }

    void serve() {
        while (!m_stop) {
            pollfd p{m_listener, POLLIN, 0};
            if (poll(&p, 1, 50) <= 0) continue;
            const int client = ::accept(m_listener, nullptr, nullptr);
            if (client < 0) continue;
            ++m_connections;
            pipe(client);  // one connection at a time, like the client under test
        }
    }

    std::string m_host;
    int m_upstreamPort;
    int m_listener = -1;
    int m_port = 0;
    std::atomic<bool> m_stop{false};
    std::atomic<int> m_connections{0};
    std::mutex m_mutex;
    Rule m_toServer;
    Rule m_toClient;
    std::thread m_thread;
};

}  // namespace tt::test
