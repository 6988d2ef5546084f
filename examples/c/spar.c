/* spar.c: a C program (C99, no C++) sparring with kumite through its C API for 10 seconds.
 *
 *   spar DB.kdb [CHARACTERS_DIR]
 *
 * The program is the tracker: it feeds a user who sways and steps in front of the fighter, orders a punch or a kick
 * every 1.5 s as a supervisor would, reads the fighter's joints each frame and prints every strike. */
#include "kumite.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int check(kumite_status status, const char* what) {
    if (status == KUMITE_OK) return 1;
    fprintf(stderr, "spar: %s: %s\n", what, kumite_last_error());
    return 0;
}

int main(int argc, char** argv) {
    if (argc < 2) {
        fprintf(stderr, "usage: spar DB.kdb [CHARACTERS_DIR]\n");
        return 2;
    }
    kumite_database* database = NULL;
    if (!check(kumite_database_open(argv[1], &database), "opening the database")) return 1;

    kumite_bout_options options;
    kumite_bout_options_init(&options);
    options.character = "brawler";
    options.characters_dir = argc > 2 ? argv[2] : NULL;
    options.aim = KUMITE_AIM_PREDICTED;
    kumite_bout* bout = NULL;
    if (!check(kumite_bout_create(database, &options, &bout), "creating the bout")) {
        kumite_database_close(database);
        return 1;
    }

    const int joints = kumite_bout_joint_count(bout, 0);
    float* transforms = (float*)malloc(sizeof(float) * 16 * (size_t)joints);
    char event[4096];
    int strikes = 0, hits = 0, frames = 0;
    const char* orders[] = {"punch", "kick", "punch left", "kick right"};
    printf("kumite %s: %d strike clips, fighter with %d joints (%s first)\n", kumite_version(), kumite_database_clip_count(database), joints,
           kumite_bout_joint_name(bout, 0, 0));
    for (int frame = 0; frame < 600; ++frame) {
        const double t = frame / 60.0;
        /* The user: 1.25 m in front, swaying 10 cm side to side, head at 1.65 m. */
        const double head[3] = {0.10 * sin(1.3 * t), 1.65 + 0.02 * sin(2.1 * t), 1.25 + 0.05 * sin(0.7 * t)};
        if (!check(kumite_bout_set_user(bout, head, NULL, NULL), "feeding the user")) break;
        if (frame % 90 == 45 && !check(kumite_bout_command(bout, orders[(frame / 90) % 4]), "ordering")) break;
        if (!check(kumite_bout_step(bout, t), "stepping")) break;
        if (!check(kumite_bout_world_transforms(bout, 0, transforms, (size_t)(16 * joints)), "reading the joints")) break;
        ++frames;
        size_t length = 0;
        while (kumite_bout_next_event(bout, event, sizeof event, &length) == 1) {
            if (strstr(event, "\"type\":\"strike\"") == NULL) continue;
            ++strikes;
            hits += strstr(event, "\"result\":\"hit\"") != NULL;
            printf("%s\n", event);
        }
    }
    /* The root's translation: column-major, so the last column holds it. */
    printf("stepped %d frames: %d strikes, %d hits; the root ends at (%.2f, %.2f, %.2f) m\n", frames, strikes, hits, transforms[12], transforms[13],
           transforms[14]);
    free(transforms);
    kumite_bout_destroy(bout);
    kumite_database_close(database);
    return frames == 600 && strikes > 0 ? 0 : 1;
}
