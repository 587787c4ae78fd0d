#pragma once
// Errors carry their context (file, call, figures) in the message; the app turns them into
// one line on stderr and an exit status. Nothing below app/ prints or exits.

#include <stdexcept>
#include <string>

namespace rad {

// Base of every error the program reports on purpose.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The user's input is wrong: a scene file, an option value. Exit status 2.
class InputError : public Error {
public:
    using Error::Error;
};

// The input names a file: the message starts with the file's path.
class FileError : public InputError {
public:
    FileError(const std::string& path, const std::string& problem)
        : InputError(path + ": " + problem), path_(path), problem_(problem) {}
    const std::string& path() const { return path_; }
    const std::string& problem() const { return problem_; }

private:
    std::string path_;
    std::string problem_;
};

// The machine failed us: OpenCL errors, allocation failures, I/O failures. Exit status 1.
class RuntimeFailure : public Error {
public:
    using Error::Error;
};

}  // namespace rad
