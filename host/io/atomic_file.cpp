#include "io/atomic_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "util/error.h"

namespace rad {

void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
    const std::string temporary = path + ".tmp-" + std::to_string(::getpid());
    try {
        {
            std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
            if (!out) throw RuntimeFailure(path + ": cannot write: " + std::strerror(errno));
            write(out);
            out.flush();
            if (!out) throw RuntimeFailure(path + ": writing failed: " + std::strerror(errno));
        }
        std::error_code ec;
        std::filesystem::rename(temporary, path, ec);
        if (ec) throw RuntimeFailure(path + ": cannot rename the finished file into place: " + ec.message());
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw;
    }
}

}  // namespace rad
