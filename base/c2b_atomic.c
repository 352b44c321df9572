#define _POSIX_C_SOURCE 200809L
#include "c2b_atomic.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

c2b_status c2b_atomic_open(c2b_atomic_file *f, const char *path, c2b_error *err)
{
    memset(f, 0, sizeof *f);
    if (!path || !*path || strlen(path) >= sizeof f->path)
        return c2b_error_set(err, C2B_ERR_IO, "output path is empty or too long");
    strcpy(f->path, path);
    snprintf(f->tmp, sizeof f->tmp, "%s.tmp-XXXXXX", path);
    int fd = mkstemp(f->tmp);
    if (fd < 0) {
        f->tmp[0] = '\0';
        return c2b_error_set(err, C2B_ERR_IO, "%s: cannot create a temporary file next to it: %s",
                             path, strerror(errno));
    }
    /* mkstemp creates 0600: give the result the mode of the file it replaces, or 0644. */
    struct stat sb;
    mode_t mode = stat(path, &sb) == 0 ? (sb.st_mode & 07777) : 0644;
    if (fchmod(fd, mode) != 0) {
        int e = errno;
        close(fd);
        unlink(f->tmp);
        f->tmp[0] = '\0';
        return c2b_error_set(err, C2B_ERR_IO, "%s: %s", path, strerror(e));
    }
    f->fp = fdopen(fd, "w");
    if (!f->fp) {
        int e = errno;
        close(fd);
        unlink(f->tmp);
        f->tmp[0] = '\0';
        return c2b_error_set(err, C2B_ERR_IO, "%s: %s", path, strerror(e));
    }
    return C2B_OK;
}

c2b_status c2b_atomic_commit(c2b_atomic_file *f, c2b_error *err)
{
    if (!f->fp)
        return c2b_error_set(err, C2B_ERR_IO, "%s: not open", f->path);
    int bad = ferror(f->fp) || fflush(f->fp) != 0 || fsync(fileno(f->fp)) != 0;
    int e = errno;
    if (fclose(f->fp) != 0 && !bad) {
        bad = 1;
        e = errno;
    }
    f->fp = NULL;
    if (!bad && rename(f->tmp, f->path) != 0) {
        bad = 1;
        e = errno;
    }
    if (bad) {
        unlink(f->tmp);
        f->tmp[0] = '\0';
        return c2b_error_set(err, C2B_ERR_IO, "%s: write failed: %s", f->path, strerror(e));
    }
    f->tmp[0] = '\0';
    return C2B_OK;
}

void c2b_atomic_abort(c2b_atomic_file *f)
{
    if (f->fp)
        fclose(f->fp);
    f->fp = NULL;
    if (f->tmp[0])
        unlink(f->tmp);
    f->tmp[0] = '\0';
}
