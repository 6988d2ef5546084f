#pragma once
// The flags of the commands that read the training store (sessions, export), and the store they name, opened.

#include "arguments.h"
#include "training_store.h"

namespace kumite::cli {

inline FlagSpec store_flag() {
    return {"store", "PATH", "the training store (default: $KUMITE_STORE, else ~/.local/share/kumite/training.sqlite)"};
}

inline FlagSpec trainee_flag() { return {"trainee", "NAME", "only this trainee's sessions (an unknown name is refused with the store's trainees)"}; }

// --store, else the default store.
inline std::filesystem::path store_path_of(const Arguments& arguments) {
    return arguments.value("store").value_or(training::default_store_path().string());
}

// The store of --store (else the default one), opened for reading, after refusing a --trainee it does not know.
inline Result<training::StoreReader> open_store_of(const Arguments& arguments) {
    Result<training::StoreReader> store = training::StoreReader::open(store_path_of(arguments));
    if (!store) return store;
    if (const std::optional<std::string> trainee = arguments.value("trainee")) {
        if (Result<void> known = store->check_trainee(*trainee); !known) return known.error();
    }
    return store;
}

} // namespace kumite::cli
