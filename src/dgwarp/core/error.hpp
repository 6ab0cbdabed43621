#pragma once
// Typed exceptions of the library. Each carries the data that was wrong so that
// a caller (the CLI, a solver) can report it or act on it. The library never
// calls exit or abort; the CLI maps these types to exit codes (see README).
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace dgwarp {

/// Base of every error the library throws on bad input or an invalid result.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// A file could not be opened, read or written (missing, permissions, disk full).
/// `error_number` is the operating system's errno when it said why (ENOENT,
/// EACCES, ...), else 0.
class IoError : public Error {
public:
    IoError(std::string file, const std::string& what, int error_number = 0)
        : Error(file + ": " + what), file_(std::move(file)), error_number_(error_number) {}
    const std::string& file() const { return file_; }
    int error_number() const { return error_number_; }

private:
    std::string file_;
    int error_number_;
};

/// A file's content is malformed: names the file, the 1-based line (0 when
/// the position is a byte offset or unknown), what was expected and what was found.
class ParseError : public Error {
public:
    ParseError(std::string file, std::size_t line, std::string expected, std::string found)
        : Error(message(file, line, expected, found)),
          file_(std::move(file)), line_(line), expected_(std::move(expected)),
          found_(std::move(found)) {}
    const std::string& file() const { return file_; }
    std::size_t line() const { return line_; }
    const std::string& expected() const { return expected_; }
    const std::string& found() const { return found_; }

private:
    static std::string message(const std::string& file, std::size_t line, const std::string& expected,
                               const std::string& found);

    std::string file_;
    std::size_t line_;
    std::string expected_;
    std::string found_;
};

/// The mesh data is inconsistent (a node id out of range, a cell of the wrong
/// dimension, an unknown marker). `marker` and `index` say where, when known.
class MeshError : public Error {
public:
    MeshError(const std::string& what, std::string marker = {}, std::int64_t index = -1)
        : Error(what), marker_(std::move(marker)), index_(index) {}
    const std::string& marker() const { return marker_; }
    std::int64_t index() const { return index_; }

private:
    std::string marker_;
    std::int64_t index_;
};

/// The file format is not supported (unknown extension, binary variant, ...).
class FormatError : public Error {
public:
    using Error::Error;
};

/// The caller's arguments are wrong: an option out of its range, or a
/// combination the call does not support (exit code 1 in the CLI, as its own
/// command-line errors).
class UsageError : public Error {
public:
    using Error::Error;
};

/// A computed result is invalid (inverted cells after a deformation, an invalid
/// moved Delaunay graph). `count` is how many items are bad.
class InvalidResultError : public Error {
public:
    InvalidResultError(const std::string& what, std::int64_t count)
        : Error(what), count_(count) {}
    std::int64_t count() const { return count_; }

private:
    std::int64_t count_;
};

}  // namespace dgwarp
