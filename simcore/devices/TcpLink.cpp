#include "simcore/devices/TcpLink.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace colonosim::devices {

namespace {
int milliseconds(double seconds)
{
    return seconds <= 0.0 ? 0 : static_cast<int>(seconds * 1000.0 + 0.999);
}

void configure(int fd)
{
    const int one = 1;
    ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL, 0) | O_NONBLOCK);
}
}  // namespace

TcpLink::TcpLink(int fd) : m_fd(fd)
{
    if (m_fd >= 0) {
        configure(m_fd);
    }
}

TcpLink::~TcpLink()
{
    close();
}

TcpLink::TcpLink(TcpLink&& other) noexcept : m_fd(other.m_fd)
{
    other.m_fd = -1;
}

TcpLink& TcpLink::operator=(TcpLink&& other) noexcept
{
    if (this != &other) {
        close();
        m_fd = other.m_fd;
        other.m_fd = -1;
    }
    return *this;
}

TcpLink TcpLink::connect(const std::string& host, int port, double timeout)
{
    if (port < 1 || port > 65535) {
        throw std::runtime_error("port = " + std::to_string(port) + " is outside [1, 65535]");
    }
    addrinfo hints{};
    hints.ai_family = AF_INET;
    hints.ai_socktype = SOCK_STREAM;
    addrinfo* found = nullptr;
    if (::getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &found) != 0 || found == nullptr) {
        throw std::runtime_error("host = \"" + host + "\" cannot be resolved");
    }
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    configure(fd);
    int rc = ::connect(fd, found->ai_addr, found->ai_addrlen);
    ::freeaddrinfo(found);
    if (rc != 0 && errno == EINPROGRESS) {
        pollfd p{fd, POLLOUT, 0};
        rc = ::poll(&p, 1, milliseconds(timeout)) == 1 ? 0 : -1;
        int error = 0;
        socklen_t length = sizeof error;
        ::getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &length);
        if (error != 0) {
            rc = -1;
        }
    }
    if (rc != 0) {
        ::close(fd);
        throw std::runtime_error("cannot connect to " + host + ":" + std::to_string(port));
    }
    return TcpLink(fd);
}

bool TcpLink::send(const std::vector<std::uint8_t>& bytes, double timeout)
{
    std::size_t sent = 0;
    while (m_fd >= 0 && sent < bytes.size()) {
        const ssize_t n = ::send(m_fd, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
        if (n > 0) {
            sent += static_cast<std::size_t>(n);
            continue;
        }
        if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
            pollfd p{m_fd, POLLOUT, 0};
            if (::poll(&p, 1, milliseconds(timeout)) == 1) {
                continue;
            }
        }
        close();
        return false;
    }
    return m_fd >= 0;
}

bool TcpLink::receive(std::vector<std::uint8_t>& out, double timeout, int wakeFd)
{
    if (m_fd < 0) {
        return false;
    }
    pollfd p[2] = {{m_fd, POLLIN, 0}, {wakeFd, POLLIN, 0}};
    if (::poll(p, wakeFd >= 0 ? 2 : 1, milliseconds(timeout)) <= 0 || p[0].revents == 0) {
        return true;
    }
    std::uint8_t buffer[4096];
    for (;;) {
        const ssize_t n = ::recv(m_fd, buffer, sizeof buffer, 0);
        if (n > 0) {
            out.insert(out.end(), buffer, buffer + n);
            continue;
        }
        if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
            return true;
        }
        close();  // 0: the peer closed; < 0: an error
        return false;
    }
}

void TcpLink::close()
{
    if (m_fd >= 0) {
        ::close(m_fd);
        m_fd = -1;
    }
}

TcpListener::TcpListener(int port, bool loopbackOnly)
{
    if (port < 0 || port > 65535) {
        throw std::runtime_error("port = " + std::to_string(port) + " is outside [0, 65535]");
    }
    m_fd = ::socket(AF_INET, SOCK_STREAM, 0);
    const int one = 1;
    ::setsockopt(m_fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(port));
    address.sin_addr.s_addr = htonl(loopbackOnly ? INADDR_LOOPBACK : INADDR_ANY);
    if (::bind(m_fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 || ::listen(m_fd, 4) != 0) {
        const std::string reason = std::strerror(errno);
        ::close(m_fd);
        m_fd = -1;
        throw std::runtime_error("cannot listen on port " + std::to_string(port) + ": " + reason);
    }
    socklen_t length = sizeof address;
    ::getsockname(m_fd, reinterpret_cast<sockaddr*>(&address), &length);
    m_port = ntohs(address.sin_port);
}

TcpListener::~TcpListener()
{
    if (m_fd >= 0) {
        ::close(m_fd);
    }
}

TcpLink TcpListener::accept(double timeout)
{
    pollfd p{m_fd, POLLIN, 0};
    if (::poll(&p, 1, milliseconds(timeout)) != 1) {
        return TcpLink();
    }
    const int fd = ::accept(m_fd, nullptr, nullptr);
    return TcpLink(fd);
}

}  // namespace colonosim::devices
