/* The C API from two threads: 100 bouts on one database (one bout per thread at a time, as kumite.h says), each
 * checked against the same bout stepped through the C++ API: the same events, byte for byte, and the same joint
 * transforms every frame. Also: errors come back as statuses with messages, never a crash.
 *
 *   c_api_threads_test DB.kdb CHARACTERS_DIR */
#include "kumite.h"
#include "reference_bout.h"

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { k_bouts = 100, k_threads = 2 };

typedef struct job {
    const kumite_database* database;
    const char* characters_dir;
    int first, stride; /* the bouts this thread runs: first, first + stride, ... */
    bout_summary summaries[k_bouts];
    int failed;
} job;

static int run_bout(const kumite_database* database, const char* characters_dir, uint64_t seed, bout_summary* summary) {
    memset(summary, 0, sizeof *summary);
    summary->events_hash = 14695981039346656037ULL;
    kumite_bout_options options;
    kumite_bout_options_init(&options);
    options.character = "brawler";
    options.characters_dir = characters_dir;
    options.tracker = "simulate:wander";
    options.seed = seed;
    kumite_bout* bout = NULL;
    if (kumite_bout_create(database, &options, &bout) != KUMITE_OK) {
        fprintf(stderr, "bout %llu: %s\n", (unsigned long long)seed, kumite_last_error());
        return 1;
    }
    const int joints = kumite_bout_joint_count(bout, 0);
    float* matrices = malloc(sizeof(float) * 16 * (size_t)joints);
    char event[8192];
    for (int frame = 0; frame < k_reference_frames; ++frame) {
        const char* order = reference_order(seed, frame);
        if (order && kumite_bout_command(bout, order) != KUMITE_OK) return 2;
        if (kumite_bout_step(bout, frame / 60.0) != KUMITE_OK) return 3;
        size_t length = 0;
        while (kumite_bout_next_event(bout, event, sizeof event, &length) == 1) {
            summary->events_hash = fnv1a(summary->events_hash, event);
            ++summary->events;
            summary->strikes += strstr(event, "\"type\":\"strike\"") != NULL;
        }
        if (kumite_bout_world_transforms(bout, 0, matrices, (size_t)(16 * joints)) != KUMITE_OK) return 4;
        for (int i = 0; i < 16 * joints; ++i) summary->transform_sum += matrices[i];
        memcpy(summary->last_root, matrices, sizeof summary->last_root);
    }
    free(matrices);
    kumite_bout_destroy(bout);
    return 0;
}

static void* run_job(void* argument) {
    job* work = argument;
    for (int b = work->first; b < k_bouts; b += work->stride) {
        if (run_bout(work->database, work->characters_dir, (uint64_t)(b + 1), &work->summaries[b]) != 0) ++work->failed;
    }
    return NULL;
}

static int expect(int condition, const char* what) {
    if (!condition) fprintf(stderr, "FAILED: %s (%s)\n", what, kumite_last_error());
    return condition ? 0 : 1;
}

int main(int argc, char** argv) {
    if (argc < 3) {
        fprintf(stderr, "usage: c_api_threads_test DB.kdb CHARACTERS_DIR\n");
        return 2;
    }
    int failures = 0;
    /* Errors: statuses and messages. */
    kumite_database* missing = NULL;
    failures += expect(kumite_database_open("/no/such/file.kdb", &missing) == KUMITE_ERROR_IO && missing == NULL, "a missing database is an io error");
    failures += expect(strstr(kumite_last_error(), "/no/such/file.kdb") != NULL, "the message names the file");
    failures += expect(kumite_database_open(NULL, &missing) == KUMITE_ERROR_ARGUMENT, "NULL path");
    kumite_database* database = NULL;
    if (kumite_database_open(argv[1], &database) != KUMITE_OK) {
        fprintf(stderr, "%s\n", kumite_last_error());
        return 1;
    }
    kumite_bout_options options;
    kumite_bout_options_init(&options);
    options.characters_dir = argv[2];
    options.character = "nobody";
    kumite_bout* bout = NULL;
    failures += expect(kumite_bout_create(database, &options, &bout) == KUMITE_ERROR_INVALID && bout == NULL, "an unknown character is invalid");
    failures += expect(strstr(kumite_last_error(), "nobody") != NULL, "the message names the character");
    options.character = NULL;
    options.tracker = "simulate:sleepy";
    failures += expect(kumite_bout_create(database, &options, &bout) == KUMITE_ERROR_INVALID, "an unknown tracker is invalid");
    options.tracker = NULL;
    failures += expect(kumite_bout_create(database, &options, &bout) == KUMITE_OK, "a fed bout");
    failures += expect(kumite_bout_command(bout, "dance") == KUMITE_ERROR_INVALID, "an unknown command is invalid");
    float too_small[16];
    failures += expect(kumite_bout_world_transforms(bout, 0, too_small, 16) == KUMITE_ERROR_ARGUMENT, "a buffer too small");
    failures += expect(kumite_bout_world_transforms(bout, 7, too_small, 16) == KUMITE_ERROR_ARGUMENT, "a fighter out of range");
    failures += expect(kumite_bout_joint_name(bout, 0, 10000) == NULL, "a joint out of range");
    const double nan_head[3] = {0.0, 0.0 / 0.0, 1.0};
    failures += expect(kumite_bout_set_user(bout, nan_head, NULL, NULL) == KUMITE_ERROR_ARGUMENT, "a head that is not finite");
    const double head[3] = {0.0, 1.65, 1.3};
    failures += expect(kumite_bout_set_user(bout, head, NULL, NULL) == KUMITE_OK, "a head");
    failures += expect(kumite_bout_command(bout, "punch") == KUMITE_OK, "an order");
    int events = 0, needed_more = 0;
    for (int frame = 0; frame < 90; ++frame) {
        failures += expect(kumite_bout_step(bout, frame / 60.0) == KUMITE_OK, "a step");
        char tiny[8];
        size_t length = 0;
        for (;;) {
            const int got = kumite_bout_next_event(bout, tiny, sizeof tiny, &length);
            if (got == 0) break;
            if (got < 0) { /* too small: it says how much, and the event stays next */
                char* big = malloc(length);
                ++needed_more;
                failures += expect(kumite_bout_next_event(bout, big, length, &length) == 1, "the event in a buffer of the size asked");
                free(big);
            }
            ++events;
        }
    }
    failures += expect(events > 0 && needed_more == events, "every event read through the size it asked for");
    if (kumite_bout_has_body(bout, 0)) {
        const int joints = kumite_bout_joint_count(bout, 0);
        float* skin = malloc(sizeof(float) * 16 * (size_t)joints);
        failures += expect(kumite_bout_skin_matrices(bout, 0, skin, (size_t)(16 * joints)) == KUMITE_OK, "skin matrices");
        free(skin);
    }
    int32_t parents[512];
    failures += expect(kumite_bout_joint_parents(bout, 0, parents, 512) == KUMITE_OK && parents[0] == -1, "the root has no parent");
    kumite_bout_destroy(bout);

    /* 100 bouts on two threads sharing the database. */
    static job jobs[k_threads];
    pthread_t threads[k_threads];
    for (int t = 0; t < k_threads; ++t) {
        jobs[t].database = database;
        jobs[t].characters_dir = argv[2];
        jobs[t].first = t;
        jobs[t].stride = k_threads;
        pthread_create(&threads[t], NULL, run_job, &jobs[t]);
    }
    for (int t = 0; t < k_threads; ++t) pthread_join(threads[t], NULL);
    int strikes = 0, same = 0;
    for (int b = 0; b < k_bouts; ++b) {
        const job* work = &jobs[b % k_threads];
        failures += work->failed;
        bout_summary reference;
        if (reference_bout(argv[1], argv[2], (uint64_t)(b + 1), &reference) != 0) {
            fprintf(stderr, "FAILED: the C++ reference of bout %d\n", b + 1);
            ++failures;
            continue;
        }
        const bout_summary* mine = &work->summaries[b];
        const int equal = mine->events == reference.events && mine->events_hash == reference.events_hash &&
                          mine->transform_sum == reference.transform_sum && memcmp(mine->last_root, reference.last_root, sizeof reference.last_root) == 0;
        if (!equal) {
            fprintf(stderr, "FAILED: bout %d differs from the C++ API: %d vs %d events, transform sums %.9g vs %.9g\n", b + 1, mine->events,
                    reference.events, mine->transform_sum, reference.transform_sum);
            ++failures;
        }
        same += equal;
        strikes += mine->strikes;
    }
    failures += expect(strikes >= k_bouts, "the bouts strike (at least one strike a bout on average)");
    printf("%d of %d bouts on %d threads equal to the C++ API's (events and transforms); %d strikes\n", same, k_bouts, k_threads, strikes);
    kumite_database_close(database);
    return failures == 0 ? 0 : 1;
}
