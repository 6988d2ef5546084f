// kumite.Store (store_binding.h): the store's tables read with StoreReader::read_table, the same columns as
// `kumite export` writes, turned into one numpy array a column.

#include "store_binding.h"

#include "training_store.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <variant>

namespace py = pybind11;

namespace kumite::python {

namespace {

py::handle g_error; // kumite.Error, which lives as long as the module

[[noreturn]] void raise_error(const std::string& message) {
    PyErr_SetString(g_error.ptr(), message.c_str());
    throw py::error_already_set();
}

template <class T>
T take(Result<T> result) {
    if (!result) raise_error(result.error().message);
    return std::move(*result);
}

void take(Result<void> result) {
    if (!result) raise_error(result.error().message);
}

// The 0/1 columns, given as bool: the store keeps them as SQLite integers.
const std::set<std::string> k_flag_columns = {"complete", "own", "countered", "defended"};

using Cell = std::variant<std::monostate, std::int64_t, double, std::string>;

struct Column {
    std::string name;
    std::vector<Cell> cells;
};

// A column's array. Flags → bool (a missing one false); integers with none missing → int64; other numbers →
// float64 with NaN for the missing; any text → object (None for the missing), as pandas.read_csv types the export.
py::array column_array(const Column& column) {
    const std::size_t n = column.cells.size();
    bool text = false, real_or_missing = false, integer = false;
    for (const Cell& cell : column.cells) {
        text |= std::holds_alternative<std::string>(cell);
        integer |= std::holds_alternative<std::int64_t>(cell);
        real_or_missing |= !std::holds_alternative<std::int64_t>(cell);
    }
    if (k_flag_columns.count(column.name)) {
        py::array_t<bool> flags(static_cast<py::ssize_t>(n));
        auto out = flags.mutable_unchecked<1>();
        for (std::size_t i = 0; i < n; ++i) {
            const auto* value = std::get_if<std::int64_t>(&column.cells[i]);
            out(py::ssize_t(i)) = value && *value != 0;
        }
        return flags;
    }
    if (text || n == 0) {
        py::list values;
        for (const Cell& cell : column.cells) {
            if (const auto* s = std::get_if<std::string>(&cell)) values.append(py::str(*s));
            else if (const auto* i = std::get_if<std::int64_t>(&cell)) values.append(py::int_(*i));
            else if (const auto* d = std::get_if<double>(&cell)) values.append(py::float_(*d));
            else values.append(py::none());
        }
        return py::module_::import("numpy").attr("array")(values, py::arg("dtype") = "object");
    }
    if (integer && !real_or_missing) {
        py::array_t<std::int64_t> integers(static_cast<py::ssize_t>(n));
        auto out = integers.mutable_unchecked<1>();
        for (std::size_t i = 0; i < n; ++i) out(py::ssize_t(i)) = std::get<std::int64_t>(column.cells[i]);
        return integers;
    }
    py::array_t<double> reals(static_cast<py::ssize_t>(n));
    auto out = reals.mutable_unchecked<1>();
    for (std::size_t i = 0; i < n; ++i) {
        const Cell& cell = column.cells[i];
        out(py::ssize_t(i)) = std::holds_alternative<double>(cell) ? std::get<double>(cell)
                              : std::holds_alternative<std::int64_t>(cell) ? double(std::get<std::int64_t>(cell))
                                                                         : std::nan("");
    }
    return reals;
}

// The columns as a pandas DataFrame when pandas imports, else a dict of numpy arrays (in the columns' order).
py::object frame(const std::vector<Column>& columns) {
    py::dict arrays;
    for (const Column& column : columns) arrays[py::str(column.name)] = column_array(column);
    try {
        py::module_ pandas = py::module_::import("pandas");
        py::list names;
        for (const Column& column : columns) names.append(column.name);
        return pandas.attr("DataFrame")(arrays, py::arg("columns") = names);
    } catch (const py::error_already_set& error) {
        if (!error.matches(PyExc_ImportError)) throw;
        return arrays;
    }
}

struct Store {
    std::string path;
    training::StoreReader reader;
};

Store store_open(const std::optional<std::string>& path) {
    const std::string chosen = path.value_or(training::default_store_path().string());
    return Store{chosen, take(training::StoreReader::open(chosen))};
}

py::object store_trainees(const Store& store) {
    std::vector<Column> columns = {{"trainee_id", {}}, {"trainee", {}}, {"sessions", {}}, {"last_utc", {}}};
    for (const training::TraineeRow& row : take(store.reader.trainees())) {
        columns[0].cells.emplace_back(row.id);
        columns[1].cells.emplace_back(row.name);
        columns[2].cells.emplace_back(std::int64_t(row.sessions));
        columns[3].cells.emplace_back(row.last_utc.empty() ? Cell() : Cell(row.last_utc));
    }
    return frame(columns);
}

// A table's rows, of one trainee's sessions and of one session when given: an unknown trainee or session raises.
py::object store_table(const Store& store, training::StoreTable table, const std::optional<std::string>& trainee, const std::optional<std::int64_t>& session) {
    if (trainee) take(store.reader.check_trainee(*trainee));
    if (session) {
        const std::vector<training::SessionRow> sessions = take(store.reader.sessions(trainee));
        if (std::none_of(sessions.begin(), sessions.end(), [&](const training::SessionRow& s) { return s.id == *session; })) {
            raise_error(store.path + ": no session " + std::to_string(*session) + (trainee ? " of trainee \"" + *trainee + "\"" : std::string()) +
                        " (kumite sessions lists them)");
        }
    }
    std::vector<Column> columns;
    std::size_t session_column = 0;
    const auto on_columns = [&](const std::vector<std::string>& names) {
        for (std::size_t c = 0; c < names.size(); ++c) {
            columns.push_back({names[c], {}});
            if (names[c] == "session_id") session_column = c;
        }
    };
    const auto on_row = [&](const std::vector<training::StoreValue>& values) {
        if (session) {
            const auto* id = std::get_if<std::int64_t>(&values[session_column]);
            if (!id || *id != *session) return;
        }
        for (std::size_t c = 0; c < values.size(); ++c) {
            const training::StoreValue& value = values[c];
            Cell& cell = columns[c].cells.emplace_back();
            if (const auto* i = std::get_if<std::int64_t>(&value)) cell = *i;
            else if (const auto* d = std::get_if<double>(&value)) cell = std::isnan(*d) ? Cell() : Cell(*d);
            else if (const auto* s = std::get_if<std::string_view>(&value)) cell = std::string(*s);
        }
    };
    take(store.reader.read_table(table, trainee, on_columns, on_row));
    return frame(columns);
}

} // namespace

void bind_store(py::module_& module) {
    g_error = module.attr("Error");
    py::class_<Store>(module, "Store", "The training store (SQLite) that `kumite train` writes, read-only.")
        .def(py::init(&store_open), py::arg("path") = py::none(),
             "Opens a store for reading: path None is the default store ($KUMITE_STORE, else ~/.local/share/kumite/training.sqlite). "
             "Raises kumite.Error for a file that is missing, not a store, damaged or from a newer kumite.")
        .def_property_readonly("path", [](const Store& store) { return store.path; })
        .def("trainees", &store_trainees, "The trainees: trainee_id, trainee, sessions, last_utc (None without sessions).")
        .def("sessions", [](const Store& store, const std::optional<std::string>& trainee) { return store_table(store, training::StoreTable::sessions, trainee, std::nullopt); },
             py::arg("trainee") = py::none(), "The sessions, oldest first (of one trainee when given): the columns of `kumite export --table sessions`.")
        .def("attacks", [](const Store& store, const std::optional<std::string>& trainee, const std::optional<std::int64_t>& session) {
            return store_table(store, training::StoreTable::attacks, trainee, session);
        }, py::arg("trainee") = py::none(), py::arg("session") = py::none(),
             "Every attack of the fighter with the trainee's response, by session then seq: the columns of `kumite export --table attacks`.")
        .def("user_strikes", [](const Store& store, const std::optional<std::string>& trainee, const std::optional<std::int64_t>& session) {
            return store_table(store, training::StoreTable::user_strikes, trainee, session);
        }, py::arg("trainee") = py::none(), py::arg("session") = py::none(),
             "The trainee's own strikes, by session then seq: the columns of `kumite export --table user_strikes`.")
        .def("__repr__", [](const Store& store) { return "<kumite.Store '" + store.path + "'>"; });
}

} // namespace kumite::python
