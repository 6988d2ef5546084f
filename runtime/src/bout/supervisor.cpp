#include "kumite/runtime/supervisor.h"

#include "kumite/runtime/combinations.h"
#include "kumite/runtime/difficulty.h"

#include <algorithm>
#include <arpa/inet.h>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace kumite {

const char* SupervisorCommand::semantics() const {
    switch (verb) {
    case Verb::kick: return "kick";
    case Verb::slash: return "slash";
    case Verb::knee: return "knee";
    case Verb::elbow: return "elbow";
    default: return "punch";
    }
}

namespace {

std::optional<SupervisorCommand::Verb> strike_verb(std::string_view word) {
    using Verb = SupervisorCommand::Verb;
    for (const Verb verb : {Verb::punch, Verb::kick, Verb::slash, Verb::knee, Verb::elbow}) {
        SupervisorCommand command;
        command.verb = verb;
        if (word == command.semantics()) return verb;
    }
    return std::nullopt;
}

} // namespace

Result<SupervisorCommand> supervisor_command_parse(std::string_view line) {
    auto next_word = [&line]() {
        const std::size_t start = line.find_first_not_of(" \t\r");
        if (start == std::string_view::npos) {
            line = {};
            return std::string_view();
        }
        line.remove_prefix(start);
        const std::size_t end = std::min(line.find_first_of(" \t\r"), line.size());
        const std::string_view word = line.substr(0, end);
        line.remove_prefix(end);
        return word;
    };
    const std::string_view verb = next_word();
    SupervisorCommand command;
    if (const std::optional<SupervisorCommand::Verb> strike = strike_verb(verb)) {
        command.verb = *strike;
        // Side, kind and height, each at most once, in any order.
        for (std::string_view word = next_word(); !word.empty(); word = next_word()) {
            const std::string text(word);
            if (word == "left" || word == "right") {
                if (!command.side.empty()) return make_error(ErrorCode::invalid, "two sides ('" + command.side + "' and '" + text + "')");
                command.side = text;
            } else if (const std::optional<StrikeKind> kind = strike_kind_from_name(word); kind && *kind != StrikeKind::none) {
                if (!strike_kind_fits(command.semantics(), *kind)) {
                    return make_error(ErrorCode::invalid, std::string("a ") + command.semantics() + " cannot be a " + text +
                                                              (verb == "punch" ? " (straight, hook, uppercut)" : verb == "kick" ? " (front, roundhouse, side)" : ""));
                }
                if (command.kind != StrikeKind::none) return make_error(ErrorCode::invalid, "two kinds ('" + std::string(strike_kind_name(command.kind)) + "' and '" + text + "')");
                command.kind = *kind;
            } else if (const std::optional<StrikeHeight> height = strike_height_from_name(word); height && *height != StrikeHeight::none) {
                if (command.height != StrikeHeight::none) return make_error(ErrorCode::invalid, "two heights ('" + std::string(strike_height_name(command.height)) + "' and '" + text + "')");
                command.height = *height;
            } else {
                return make_error(ErrorCode::invalid, "'" + text + "' is not a side (left, right), a kind or a height (low, middle, high)");
            }
        }
        return command;
    }
    const std::string_view argument = next_word();
    const std::string_view extra = next_word();
    if (!extra.empty()) return make_error(ErrorCode::invalid, "too many words");
    if (verb == "character") {
        if (argument.empty()) return make_error(ErrorCode::invalid, "character needs a NAME");
        command.verb = SupervisorCommand::Verb::character;
        command.argument = argument;
    } else if (verb == "aim") {
        if (argument != "latched" && argument != "predicted") {
            return make_error(ErrorCode::invalid, "aim must be latched or predicted, not '" + std::string(argument) + "'");
        }
        command.verb = SupervisorCommand::Verb::aim;
        command.argument = argument;
    } else if (verb == "defence") {
        if (argument != "on" && argument != "off") return make_error(ErrorCode::invalid, "defence must be on or off, not '" + std::string(argument) + "'");
        command.verb = SupervisorCommand::Verb::defence;
        command.argument = argument;
    } else if (verb == "combo") {
        if (combination_index(argument) < 0) {
            return make_error(ErrorCode::invalid, "combo takes " + std::string(combination_names()) + ", not '" + std::string(argument) + "'");
        }
        command.verb = SupervisorCommand::Verb::combo;
        command.argument = argument;
    } else if (verb == "difficulty") {
        if (!difficulty_find(argument)) return make_error(ErrorCode::invalid, "difficulty takes " + std::string(difficulty_names()) + ", not '" + std::string(argument) + "'");
        command.verb = SupervisorCommand::Verb::difficulty;
        command.argument = argument;
    } else if (verb == "spar") {
        if (argument != "on" && argument != "off") return make_error(ErrorCode::invalid, "spar must be on or off, not '" + std::string(argument) + "'");
        command.verb = SupervisorCommand::Verb::spar;
        command.argument = argument;
    } else if (verb == "quit") {
        if (!argument.empty()) return make_error(ErrorCode::invalid, "quit takes nothing");
        command.verb = SupervisorCommand::Verb::quit;
    } else {
        return make_error(ErrorCode::invalid, "unknown command '" + std::string(verb) + "' (punch, kick, slash, knee, elbow, combo, character, aim, defence, difficulty, spar, quit)");
    }
    return command;
}

Result<CommandScript> CommandScript::read(const std::string& path) {
    std::ifstream in(path);
    if (!in) return make_error(ErrorCode::io, path + ": cannot read the command script");
    CommandScript script;
    std::string text;
    for (int number = 1; std::getline(in, text); ++number) {
        if (!text.empty() && text.back() == '\r') text.pop_back();
        const std::size_t first = text.find_first_not_of(" \t");
        if (first == std::string::npos || text[first] == '#') continue;
        std::istringstream stream(text);
        Line line;
        line.line = number;
        if (!(stream >> line.t_s) || !std::isfinite(line.t_s) || line.t_s < 0) {
            return make_error(ErrorCode::parse, path + ":" + std::to_string(number) + ": expected '<time_s> <command>'");
        }
        std::getline(stream >> std::ws, line.command);
        script.m_lines.push_back(std::move(line));
    }
    std::stable_sort(script.m_lines.begin(), script.m_lines.end(), [](const Line& a, const Line& b) { return a.t_s < b.t_s; });
    return script;
}

void CommandScript::due(double t_s, const std::function<void(const Line&)>& on_line) {
    for (; m_next < m_lines.size() && m_lines[m_next].t_s <= t_s; ++m_next) on_line(m_lines[m_next]);
}

Result<std::unique_ptr<CommandStream>> CommandStream::open(std::string_view source) {
    std::unique_ptr<CommandStream> stream(new CommandStream());
    if (source == "stdin") {
        stream->m_stdin = true;
        stream->m_client = 0;
        fcntl(0, F_SETFL, fcntl(0, F_GETFL) | O_NONBLOCK);
        return stream;
    }
    if (!source.starts_with("tcp:")) return make_error(ErrorCode::invalid, "commands come from stdin or tcp:PORT, not '" + std::string(source) + "'");
    char* end = nullptr;
    const std::string port_text(source.substr(4));
    const long port = std::strtol(port_text.c_str(), &end, 10);
    if (port_text.empty() || *end != '\0' || port < 0 || port > 65535) return make_error(ErrorCode::invalid, "tcp:PORT needs a port number");
    stream->m_listen = socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    if (stream->m_listen < 0) return make_error(ErrorCode::io, "cannot create a TCP socket: " + std::string(std::strerror(errno)));
    const int yes = 1;
    setsockopt(stream->m_listen, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK); // the supervisor's console is on this machine
    if (bind(stream->m_listen, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 || listen(stream->m_listen, 1) != 0) {
        return make_error(ErrorCode::io, "tcp:" + port_text + ": cannot listen on 127.0.0.1: " + std::strerror(errno));
    }
    socklen_t length = sizeof address;
    getsockname(stream->m_listen, reinterpret_cast<sockaddr*>(&address), &length);
    stream->m_port = ntohs(address.sin_port);
    return stream;
}

CommandStream::~CommandStream() {
    if (m_client > 0) close(m_client);
    if (m_listen >= 0) close(m_listen);
}

void CommandStream::drain(int fd, const std::function<void(std::string_view)>& on_line) {
    char buffer[1024];
    while (true) {
        const ssize_t size = read(fd, buffer, sizeof buffer);
        if (size == 0 && !m_stdin) { // the supervisor hung up: wait for the next one
            close(m_client);
            m_client = -1;
            m_length = 0;
            return;
        }
        if (size <= 0) return;
        for (ssize_t i = 0; i < size; ++i) {
            const char c = buffer[i];
            if (c == '\n') {
                if (!m_overlong) on_line(std::string_view(m_line.data(), m_length));
                else reply("error: line too long\n");
                m_length = 0;
                m_overlong = false;
            } else if (m_length < m_line.size()) {
                m_line[m_length++] = c;
            } else {
                m_overlong = true;
            }
        }
    }
}

void CommandStream::poll(const std::function<void(std::string_view)>& on_line) {
    if (m_stdin) return drain(0, on_line);
    if (m_client < 0) {
        m_client = accept4(m_listen, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
        if (m_client < 0) return;
    }
    drain(m_client, on_line);
}

void CommandStream::reply(std::string_view text) {
    if (m_stdin) {
        std::fwrite(text.data(), 1, text.size(), stdout);
        std::fflush(stdout);
    } else if (m_client >= 0) {
        const ssize_t ignored = send(m_client, text.data(), text.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
        (void)ignored;
    }
}

} // namespace kumite
