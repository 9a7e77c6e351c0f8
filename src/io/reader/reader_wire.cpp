#include "io/reader/reader_wire.h"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <sstream>

namespace flowsurf::io::wire {

template <>
bool Writer::flush() {
    size_t done = 0;
    bool ok = true;
    while (done < buf_.size()) {
        ssize_t n = ::send(fd_, buf_.data() + done, buf_.size() - done, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            ok = false;
            break;
        }
        done += size_t(n);
    }
    buf_.clear();
    return ok;
}

template <>
void Writer::raw(const void* data, size_t bytes) {
    const char* p = static_cast<const char*>(data);
    buf_.insert(buf_.end(), p, p + bytes);
    if (buf_.size() > (size_t(1) << 20)) flush();
}

template <>
void Reader::raw(void* data, size_t bytes) {
    char* p = static_cast<char*>(data);
    while (bytes > 0) {
        if (deadline_ != Clock::time_point::max()) {
            auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline_ - Clock::now()).count();
            if (left <= 0) throw Broken{true};
            pollfd pfd{fd_, POLLIN, 0};
            int rc = ::poll(&pfd, 1, int(std::min<long long>(left, 1 << 30)));
            if (rc < 0 && errno == EINTR) continue;
            if (rc == 0) throw Broken{true};
            if (rc < 0) throw Broken{};
        }
        ssize_t n = ::recv(fd_, p, bytes, 0);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw Broken{};
        p += n;
        bytes -= size_t(n);
    }
}

std::string stepLabel(const std::string& path, const std::vector<double>& times, size_t index) {
    if (times.size() <= 1) return path;
    std::ostringstream s;
    s << path << " (time step " << index + 1 << " of " << times.size() << ", t = " << times[index] << ")";
    return s.str();
}

}  // namespace flowsurf::io::wire
