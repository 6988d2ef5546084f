#pragma once
// Result<T>: a value or an Error, for everything driven by input (files, text, sockets, command lines).
// Member names follow std::expected (has_value, value, error, operator*, operator->) so a later switch to
// C++23 is a rename. Broken contracts assert instead; no exception crosses a library boundary.

#include <cassert>
#include <string>
#include <utility>
#include <variant>

namespace kumite {

enum class ErrorCode {
    io,          // a file could not be opened, read, written or renamed
    parse,       // the text does not follow the format's grammar
    invalid,     // well-formed input whose content is wrong (out of range, inconsistent)
    unsupported, // a legal construct this program does not handle
    limit,       // input exceeds a safety limit (size, count, depth)
};

struct Error {
    ErrorCode code = ErrorCode::invalid;
    std::string message; // says what, where (file:line, byte offset) and, when useful, what to do
};

template <class T>
class [[nodiscard]] Result {
public:
    Result(T value) : m_storage(std::move(value)) {}
    Result(Error error) : m_storage(std::move(error)) {}

    bool has_value() const { return m_storage.index() == 0; }
    explicit operator bool() const { return has_value(); }

    T& value() & { assert(has_value()); return std::get<0>(m_storage); }
    const T& value() const& { assert(has_value()); return std::get<0>(m_storage); }
    T&& value() && { assert(has_value()); return std::get<0>(std::move(m_storage)); }
    const Error& error() const { assert(!has_value()); return std::get<1>(m_storage); }

    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }

private:
    std::variant<T, Error> m_storage;
};

template <>
class [[nodiscard]] Result<void> {
public:
    Result() = default;
    Result(Error error) : m_error(std::move(error)), m_failed(true) {}

    bool has_value() const { return !m_failed; }
    explicit operator bool() const { return has_value(); }
    const Error& error() const { assert(m_failed); return m_error; }

private:
    Error m_error;
    bool m_failed = false;
};

inline Error make_error(ErrorCode code, std::string message) { return Error{code, std::move(message)}; }

} // namespace kumite
