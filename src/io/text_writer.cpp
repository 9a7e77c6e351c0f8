#include "io/text_writer.h"

#include "core/errors.h"
#include "io/temp_file.h"

#include <cerrno>
#include <unistd.h>

namespace flowsurf::io {

void writeTextFile(const std::string& path, const std::string& content) {
    detail::TempFile tmp(path);
    size_t done = 0;
    while (done < content.size()) {
        ssize_t n = ::write(tmp.fd(), content.data() + done, content.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw IoError(detail::writeErrorMessage(path, errno));
        done += size_t(n);
    }
    tmp.commit();
}

}  // namespace flowsurf::io
