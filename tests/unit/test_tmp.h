/* test_tmp.h - scratch files of a unit test: tmp_path(name) is name inside
 * the test's temporary folder tmpdir (made by its main with mkdtemp; four
 * results live at once), write_text writes a whole text file. */
#ifndef GR_TEST_TMP_H
#define GR_TEST_TMP_H

#include <stdio.h>

static char tmpdir[64];

static inline const char *tmp_path(const char *name)
{
    static char buf[4][160];
    static int k;
    k = (k + 1) % 4;
    snprintf(buf[k], sizeof buf[k], "%s/%s", tmpdir, name);
    return buf[k];
}

static inline void write_text(const char *path, const char *text)
{
    FILE *fp = fopen(path, "w");
    fputs(text, fp);
    fclose(fp);
}

#endif
