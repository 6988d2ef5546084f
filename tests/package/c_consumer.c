/* An integrator's C program against the installed package: kumite.h and libkumite (kumite::c). */
#include <kumite.h>

#include <stdio.h>
#include <string.h>

int main(void) {
    kumite_database* database = NULL;
    /* No database at that path: a status and a message, not a crash. */
    if (kumite_database_open("/no/such.kdb", &database) != KUMITE_ERROR_IO || strstr(kumite_last_error(), "/no/such.kdb") == NULL) return 1;
    printf("libkumite %s: %s\n", kumite_version(), kumite_last_error());
    return 0;
}
