#pragma once
/// \file
/// TCP over POSIX sockets for the HDC link: non-blocking, Nagle off
/// (TCP_NODELAY) so each small message leaves at once, and poll() with a
/// timeout so neither side's loop ever blocks on the network for longer
/// than it chooses. OpenIGTLink frames the bytes (IgtlMessages.h).

#include <cstdint>
#include <string>
#include <vector>

namespace colonosim::devices {

class TcpLink {
public:
    TcpLink() = default;
    explicit TcpLink(int fd);
    ~TcpLink();
    TcpLink(TcpLink&& other) noexcept;
    TcpLink& operator=(TcpLink&& other) noexcept;
    TcpLink(const TcpLink&) = delete;
    TcpLink& operator=(const TcpLink&) = delete;

    /// Connects to host:port within timeout (s); throws std::runtime_error with the reason.
    static TcpLink connect(const std::string& host, int port, double timeout);

    [[nodiscard]] bool open() const { return m_fd >= 0; }
    /// Sends all of it (waits at most `timeout` s for the socket); false closes the link.
    bool send(const std::vector<std::uint8_t>& bytes, double timeout = 0.1);
    /// Appends what has arrived within `timeout` s to `out`; false when the peer closed.
    /// A readable `wakeFd` (e.g. an eventfd) ends the wait early.
    bool receive(std::vector<std::uint8_t>& out, double timeout, int wakeFd = -1);
    void close();

private:
    int m_fd = -1;
};

/// A listening socket on the loopback or all interfaces.
class TcpListener {
public:
    /// Port 0 picks a free port (see port()). Throws std::runtime_error.
    explicit TcpListener(int port, bool loopbackOnly = true);
    ~TcpListener();
    TcpListener(const TcpListener&) = delete;
    TcpListener& operator=(const TcpListener&) = delete;

    [[nodiscard]] int port() const { return m_port; }
    /// A new connection within `timeout` s, or a closed link.
    TcpLink accept(double timeout);

private:
    int m_fd = -1;
    int m_port = 0;
};

}  // namespace colonosim::devices
