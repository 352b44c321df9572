/* Replays fuzz inputs without libFuzzer: `replay_X FILE_OR_DIR...` runs the target's
 * LLVMFuzzerTestOneInput on every file given (directories: every file inside). The
 * ctests (label fuzz) replay the whole seed corpus, including every input the fuzzers
 * ever crashed on, in the normal and in the sanitizer builds. */
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#ifdef __cplusplus
extern "C"
#endif
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int replay_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "replay: cannot open %s\n", path);
        return 1;
    }
    size_t cap = 1 << 16, len = 0;
    uint8_t *buf = malloc(cap);
    for (;;) {
        if (!buf) {
            fclose(f);
            return 1;
        }
        len += fread(buf + len, 1, cap - len, f);
        if (len < cap)
            break;
        uint8_t *nb = realloc(buf, cap * 2);
        if (!nb)
            free(buf);
        buf = nb;
        cap *= 2;
    }
    fclose(f);
    LLVMFuzzerTestOneInput(buf, len);
    free(buf);
    printf("ok   %s\n", path);
    return 0;
}

int main(int argc, char **argv)
{
    int fails = 0, n = 0;
    for (int i = 1; i < argc; i++) {
        struct stat st;
        if (stat(argv[i], &st) == 0 && S_ISDIR(st.st_mode)) {
            DIR *d = opendir(argv[i]);
            struct dirent *e;
            while (d && (e = readdir(d))) {
                if (e->d_name[0] == '.')
                    continue;
                char p[4096];
                snprintf(p, sizeof p, "%s/%s", argv[i], e->d_name);
                fails += replay_file(p);
                n++;
            }
            if (d)
                closedir(d);
        } else {
            fails += replay_file(argv[i]);
            n++;
        }
    }
    printf("replayed %d inputs, %d unreadable\n", n, fails);
    return fails != 0 || n == 0;
}
