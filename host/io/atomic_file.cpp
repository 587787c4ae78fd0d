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

void checkOutputFile(const std::string& option, const std::string& path, const std::string& folderToBeMade) {
    if (path.empty()) throw InputError(option + ": needs a file name");
    const std::filesystem::path file(path);
    std::error_code ec;
    if (std::filesystem::is_directory(file, ec)) throw InputError(option + " " + path + ": is a folder");
    const std::filesystem::path folder = file.parent_path();
    // (through a child name, so that "out/" and "out" are the same folder)
    const bool made = !folderToBeMade.empty() && !folder.empty() &&
                      folder.lexically_normal() ==
                          (std::filesystem::path(folderToBeMade) / "x").lexically_normal().parent_path();
    if (!folder.empty() && !made && !std::filesystem::is_directory(folder, ec))
        throw InputError(option + " " + path + ": its folder does not exist");
}

}  // namespace rad
