#pragma once
// Supervisor commands, one per line: `punch [left|right] [straight|hook|uppercut] [low|middle|high]`,
// `kick [left|right] [front|roundhouse|side] [low|middle|high]` (any of the three, in any order; `other` is a kind
// too), `slash`, `knee`, `elbow [left|right] [low|middle|high]`,
// `combo one-two|jab-hook|jab-body-head` (combinations.h), `character NAME`, `aim latched|predicted`, `defence on|off`,
// `difficulty LEVEL` (difficulty.h), `spar on|off` (the fighter's own attacks), `quit`. They come
// from a script file (`<time_s> <command>` lines), stdin, or a TCP connection on 127.0.0.1 (the port is opt-in).
// Streams are read without blocking from the frame loop; an unknown line is answered with an error line (on stdout
// for stdin, on the connection for TCP) and ignored.

#include "kumite/core/result.h"
#include "kumite/core/strike_labels.h"

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace kumite {

struct SupervisorCommand {
    enum class Verb { punch, kick, slash, knee, elbow, combo, character, aim, defence, difficulty, spar, quit } verb = Verb::punch;
    std::string side;      // "", "left" or "right" for strikes
    StrikeKind kind = StrikeKind::none;       // strikes: none = any
    StrikeHeight height = StrikeHeight::none; // strikes: none = any
    std::string argument;  // the character's name, the aim mode, the combination's name, the level, on/off
    bool is_strike() const { return verb <= Verb::elbow; }
    const char* semantics() const;
};

// Parses one line; an error says what is wrong with it.
Result<SupervisorCommand> supervisor_command_parse(std::string_view line);

// A script of timed commands: `<time_s> <command>` per line, `#` comments and blank lines skipped; kept in time
// order (lines with equal times in file order).
class CommandScript {
public:
    struct Line {
        double t_s = 0.0;
        std::string command;
        int line = 0; // in the file, for messages
    };
    static Result<CommandScript> read(const std::string& path);
    // Calls `on_line` for every line due at t that was not handed out yet.
    void due(double t_s, const std::function<void(const Line&)>& on_line);

private:
    std::vector<Line> m_lines;
    std::size_t m_next = 0;
};

class CommandStream {
public:
    // "stdin" or "tcp:PORT" (listens on 127.0.0.1:PORT; port 0 picks a free one).
    static Result<std::unique_ptr<CommandStream>> open(std::string_view source);
    ~CommandStream();
    CommandStream(const CommandStream&) = delete;
    CommandStream& operator=(const CommandStream&) = delete;

    // Reads what has arrived and calls `on_line` for each complete line. Never blocks.
    void poll(const std::function<void(std::string_view line)>& on_line);
    // Answers the source (stdout, or the TCP client).
    void reply(std::string_view text);
    int port() const { return m_port; }

private:
    CommandStream() = default;
    void drain(int fd, const std::function<void(std::string_view)>& on_line);

    int m_listen = -1;  // TCP: the listening socket
    int m_client = -1;  // TCP: the connected supervisor; stdin: 0
    int m_port = 0;
    bool m_stdin = false;
    std::array<char, 4096> m_line{};
    std::size_t m_length = 0;
    bool m_overlong = false;
};

} // namespace kumite
