/**
 * @file c2b_atomic.h
 * Atomic file output: write to a temporary file in the destination's directory and
 * rename it over the destination only when everything was written, so a reader never
 * sees a half-written file and a failed write leaves the old file untouched.
 */
#ifndef C2B_ATOMIC_H
#define C2B_ATOMIC_H

#include <stdio.h>

#include "c2b_error.h"

#ifdef __cplusplus
extern "C" {
#endif

/** An output file being written. Caller-owned; fields are private. */
typedef struct c2b_atomic_file {
    FILE *fp;           /**< write through this stream */
    char path[4096];    /**< destination */
    char tmp[4096 + 16];/**< temporary name */
} c2b_atomic_file;

/**
 * Create "<path>.tmp-XXXXXX" and open it for writing. The final file keeps the mode of
 * the file it replaces (0644 for a new file).
 * @return C2B_OK; C2B_ERR_IO naming the path and the system error.
 */
c2b_status c2b_atomic_open(c2b_atomic_file *f, const char *path, c2b_error *err);

/**
 * Flush, close and rename the temporary over the destination. On failure the
 * temporary is removed.
 * @return C2B_OK; C2B_ERR_IO (disk full, rename refused, ...).
 */
c2b_status c2b_atomic_commit(c2b_atomic_file *f, c2b_error *err);

/** Close and remove the temporary; the destination is untouched. Safe after a failed
 *  open or a commit (then a no-op). */
void c2b_atomic_abort(c2b_atomic_file *f);

#ifdef __cplusplus
}
#endif
#endif
