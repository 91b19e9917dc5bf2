/*
 * The version check a program linked to libsafelogic makes (docs/release.md): at compile
 * time against the header it is built with, at run time against the library it loaded.
 *
 *   cc version_check.c $(pkg-config --cflags --libs safelogic)
 *   cc -static version_check.c $(pkg-config --static --cflags --libs safelogic)
 */
#include <stdio.h>

#include "safelogic.h"

/* Written for the 1.x C ABI: a header of another major fails the build here. */
#if !defined(SL_VERSION_MAJOR) || SL_VERSION_MAJOR != 1
#error "safelogic.h of C ABI major 1 required"
#endif

int main(void)
{
    /* The loaded library must serve this header: same major, minor not older. */
    if (!sl_version_compatible(SL_VERSION_MAJOR, SL_VERSION_MINOR)) {
        fprintf(stderr, "libsafelogic %s does not serve safelogic.h %d.%d.%d\n", sl_version(),
                SL_VERSION_MAJOR, SL_VERSION_MINOR, SL_VERSION_PATCH);
        return 1;
    }
    printf("safelogic.h %d.%d.%d, libsafelogic %s: compatible\n", SL_VERSION_MAJOR,
           SL_VERSION_MINOR, SL_VERSION_PATCH, sl_version());
    return 0;
}
