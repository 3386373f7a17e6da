#pragma once
// The one error type for a user's mistake: "FILE: WHERE: WHAT". main() prints it on one
// line and exits 1; no abort, no stack trace.

#include <stdexcept>
#include <string>

namespace rt {

class Error : public std::runtime_error {
  public:
    Error(std::string file, std::string where, std::string what)
        : std::runtime_error(file + ": " + where + ": " + what),
          file_(std::move(file)),
          where_(std::move(where)),
          what_(std::move(what)) {}

    const std::string& file() const { return file_; }
    const std::string& where() const { return where_; }
    const std::string& detail() const { return what_; }

  private:
    std::string file_;
    std::string where_;
    std::string what_;
};

}  // namespace rt
