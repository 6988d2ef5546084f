/* The C API test's reference: the same bout stepped through the C++ API (kumite::Bout), summarised as the C test
 * summarises its own. */
#ifndef KUMITE_TEST_REFERENCE_BOUT_H
#define KUMITE_TEST_REFERENCE_BOUT_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct bout_summary {
    int events;
    int strikes;
    uint64_t events_hash;  /* FNV-1a over every event's JSON line, in order */
    double transform_sum;  /* every float of every joint's world matrix, every frame, summed in order */
    float last_root[16];   /* the root's world matrix after the last step */
} bout_summary;

enum { k_reference_frames = 240 };
/* The order a bout of seed `seed` gets at frame `frame`, or NULL. */
const char* reference_order(uint64_t seed, int frame);
/* Runs the bout of `seed` (simulate:wander, brawler) through the C++ API. 0 on success. */
int reference_bout(const char* database_path, const char* characters_dir, uint64_t seed, bout_summary* summary);
uint64_t fnv1a(uint64_t hash, const char* text);

#ifdef __cplusplus
}
#endif

#endif
