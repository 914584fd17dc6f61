// How loaders report problems: a LoadError (fatal, exit status 1) whose message starts with
// "file:line:", and warnings that are collected for the caller to print.
#pragma once

#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace pt {

class LoadError : public std::runtime_error {
public:
    explicit LoadError(const std::string& message) : std::runtime_error(message) {}
    LoadError(const std::string& file, size_t line, const std::string& message)
        : std::runtime_error(file + ":" + std::to_string(line) + ": " + message) {}
};

class Warnings {
public:
    static constexpr size_t kMaxMessages = 50; // a garbage file must not print a million lines

    void add(std::string message) {
        if (messages_.size() < kMaxMessages) messages_.push_back(std::move(message));
        else if (messages_.size() == kMaxMessages) messages_.push_back("further warnings not shown");
    }
    // Adds the message only the first time `key` is seen, so a keyword used on every line of a
    // file is reported once.
    void once(const std::string& key, std::string message) {
        if (seen_.insert(key).second) add(std::move(message));
    }
    const std::vector<std::string>& messages() const { return messages_; }

private:
    std::vector<std::string> messages_;
    std::set<std::string> seen_;
};

} // namespace pt
