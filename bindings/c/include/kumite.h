/* kumite.h: the sparring fighter behind a C ABI (C99), for engines and languages that reach native code through C
 * (Unity P/Invoke, Godot GDExtension, Unreal plugins, Rust, C#, Python ctypes). Link libkumite (shared); it exports
 * only the kumite_* functions below.
 *
 * Ownership: every object kumite_*_open/_create returns is the caller's, released with the matching
 * _close/_destroy. A database must outlive the bouts created on it. Buffers passed in are the caller's; kumite keeps
 * no pointer to them after the call returns. Strings kumite returns (names, error messages) stay valid as said at
 * each function.
 *
 * Threads: a database is read-only once open (a memory-mapped file) and may be shared by bouts on any threads. A
 * bout is used by one thread at a time (calls on one bout must not overlap; moving a bout between threads between
 * calls is fine). kumite_last_error is per thread.
 *
 * Errors: every function that can fail returns a kumite_status; on failure kumite_last_error() says what and where
 * (file:line for bad files). No exception and no abort crosses this boundary: an unexpected failure inside kumite
 * (out of memory) is KUMITE_ERROR_INTERNAL.
 *
 * Cost: kumite_bout_step, kumite_bout_set_user and the transform reads allocate nothing. Reading an event formats
 * JSON and allocates (events are a few a second). Units: metres, seconds, radians; axes right-handed, Y up.
 */
#ifndef KUMITE_H
#define KUMITE_H

#include <stddef.h>
#include <stdint.h>

#if defined(_WIN32)
#define KUMITE_API __declspec(dllexport)
#else
#define KUMITE_API __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
extern "C" {
#endif

typedef enum kumite_status {
    KUMITE_OK = 0,
    KUMITE_ERROR_IO = 1,       /* a file could not be opened, read or mapped */
    KUMITE_ERROR_PARSE = 2,    /* a file does not follow its format (a corrupt database, a malformed BVH) */
    KUMITE_ERROR_INVALID = 3,  /* well-formed input that is wrong: an unknown character, command or tracker */
    KUMITE_ERROR_ARGUMENT = 4, /* a null pointer, an index out of range, a buffer too small */
    KUMITE_ERROR_INTERNAL = 5  /* an unexpected failure inside kumite (out of memory) */
} kumite_status;

typedef enum kumite_aim {
    KUMITE_AIM_LATCHED = 0,  /* strike where the head was at the order (the paper's) */
    KUMITE_AIM_PREDICTED = 1 /* strike where the head will be at the contact */
} kumite_aim;

typedef struct kumite_database kumite_database;
typedef struct kumite_bout kumite_bout;

/* "0.1.0": the library's version. Static storage. */
KUMITE_API const char* kumite_version(void);

/* The message of the last failed call on this thread ("" if none). Valid until the next failing call on this thread. */
KUMITE_API const char* kumite_last_error(void);

/* Opens (memory-maps and validates) a motion database (.kdb, written by `kumite bake`). */
KUMITE_API kumite_status kumite_database_open(const char* path, kumite_database** database);
/* Closes it; every bout created on it must be destroyed first. NULL is ignored. */
KUMITE_API void kumite_database_close(kumite_database* database);
/* Strike clips in the database (mirrors included). */
KUMITE_API int kumite_database_clip_count(const kumite_database* database);

typedef struct kumite_bout_options {
    const char* character;      /* a character of characters_dir by name, or a .bvh/.glb/.gltf path; NULL: the first */
    const char* characters_dir; /* NULL: $KUMITE_CHARACTERS_DIR, else kumite's data/characters */
    const char* tracker;        /* NULL: the caller feeds the user (kumite_bout_set_user); else a source as
                                   `kumite play --tracker` takes it: simulate:still|wander|walk[:SPEED]|dodge|dodge-seen|punch,
                                   replay:FILE.csv, capture:FILE.bvh[:DISTANCE[:START_S]], dtrack:PORT[...] */
    int fighters;               /* side by side against the same user; default 1 */
    int aim;                    /* kumite_aim; default KUMITE_AIM_LATCHED */
    int defence;                /* 1: block and slip the user's strikes (default), 0: not */
    uint64_t seed;              /* simulated users; default 1 */
    double rate_hz;             /* steps per second the bout expects; default 60 */
} kumite_bout_options;

/* Fills the defaults. Always call it first: later versions may add fields at the end. */
KUMITE_API void kumite_bout_options_init(kumite_bout_options* options);

/* A bout on `database` (it must outlive the bout). */
KUMITE_API kumite_status kumite_bout_create(const kumite_database* database, const kumite_bout_options* options, kumite_bout** bout);
/* NULL is ignored. */
KUMITE_API void kumite_bout_destroy(kumite_bout* bout);

/* The tracked user for the next steps, world metres: `head` NULL means not tracked (the fighter holds its guard);
 * a hand NULL means not tracked. Only for a bout whose options.tracker was NULL. */
KUMITE_API kumite_status kumite_bout_set_user(kumite_bout* bout, const double head[3], const double left_hand[3], const double right_hand[3]);

/* A supervisor command line, applied at the next step: "punch [left|right] [straight|hook|uppercut] [low|middle|high]",
 * "kick ...", "knee ...", "elbow ...", "character NAME", "aim latched|predicted", "defence on|off". An unknown
 * line is KUMITE_ERROR_INVALID with the reason. */
KUMITE_API kumite_status kumite_bout_command(kumite_bout* bout, const char* line);

/* One frame at time t_s (seconds from the bout's start, increasing by about 1/rate_hz). Afterwards the poses and
 * this step's events can be read. */
KUMITE_API kumite_status kumite_bout_step(kumite_bout* bout, double t_s);

KUMITE_API int kumite_bout_fighter_count(const kumite_bout* bout);
/* The fighter's current character: its joints (they change when the character does: read them again after a
 * `character` event). -1 for a fighter out of range. */
KUMITE_API int kumite_bout_joint_count(const kumite_bout* bout, int fighter);
/* A joint's name; valid until the bout is destroyed. NULL when out of range. */
KUMITE_API const char* kumite_bout_joint_name(const kumite_bout* bout, int fighter, int joint);
/* Each joint's parent index (-1 for the root) into parents[0 .. joint_count-1]; `count` is the array's length. */
KUMITE_API kumite_status kumite_bout_joint_parents(const kumite_bout* bout, int fighter, int32_t* parents, size_t count);
/* Each joint's world transform as of the last step, a 4x4 column-major matrix (16 floats per joint, rotation and
 * translation in metres), into matrices[0 .. 16*joint_count-1]; `count` is the array's length in floats. */
KUMITE_API kumite_status kumite_bout_world_transforms(const kumite_bout* bout, int fighter, float* matrices, size_t count);
/* 1 when the fighter's current character has a skinned body (a glTF character), else 0. */
KUMITE_API int kumite_bout_has_body(const kumite_bout* bout, int fighter);
/* Linear-blend skinning matrices for that body (16 floats per joint, column-major; a bind-space vertex v goes to
 * sum_k w_k * S[joint_k] * v). KUMITE_ERROR_INVALID when the character has no body. */
KUMITE_API kumite_status kumite_bout_skin_matrices(const kumite_bout* bout, int fighter, float* matrices, size_t count);

/* The next event of the last step as one line of JSON ({"t", "type", "fighter", ...}: the lines of
 * `kumite play --events`), copied with its terminating zero into buffer[0 .. capacity-1]. Returns 1 when an event was
 * written, 0 when this step's events are all read, -1 on error (KUMITE_ERROR_ARGUMENT: *length then says the
 * size needed, zero included; the event stays next). `length` may be NULL. */
KUMITE_API int kumite_bout_next_event(kumite_bout* bout, char* buffer, size_t capacity, size_t* length);

#ifdef __cplusplus
}
#endif

#endif /* KUMITE_H */
