/**
 * @file c2b_error.h
 * Status codes and the error record that every fallible C2Blend function fills.
 *
 * Convention: a fallible function returns a ::c2b_status and takes an optional
 * `c2b_error *err` as its last argument. On failure the record holds the same code
 * and a message that names the spec field, mode or object at fault. Passing NULL
 * discards the message. The library never prints and never aborts.
 */
#ifndef C2B_ERROR_H
#define C2B_ERROR_H

#ifdef __cplusplus
extern "C" {
#endif

/** Status codes. The CLI maps SPEC/ARG/LIMIT/IO to exit code 2 and NUMERIC to 3. */
typedef enum c2b_status {
    C2B_OK = 0,          /**< success */
    C2B_ERR_ARG = 1,     /**< invalid argument passed by the caller (NULL, bad size) */
    C2B_ERR_SPEC = 2,    /**< invalid spec or boundary data; the message names the field */
    C2B_ERR_NUMERIC = 3, /**< resonant or ill-conditioned mode, non-finite result */
    C2B_ERR_NOMEM = 4,   /**< allocation failed */
    C2B_ERR_IO = 5,      /**< a file could not be read or written */
    C2B_ERR_LIMIT = 6    /**< a request exceeds a documented size limit */
} c2b_status;

/** Length of the message buffer in ::c2b_error, terminating NUL included. */
#define C2B_ERROR_MSG_LEN 1024

/** Error record: the code and a human-readable message naming what is wrong and where. */
typedef struct c2b_error {
    c2b_status code;
    char msg[C2B_ERROR_MSG_LEN];
} c2b_error;

/**
 * Record an error. `err` may be NULL (then only the code is returned).
 * The message is printf-formatted and truncated to fit.
 * @return `code`, so callers can write `return c2b_error_set(err, C2B_ERR_SPEC, ...)`.
 */
c2b_status c2b_error_set(c2b_error *err, c2b_status code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/**
 * Prefix the message already in `err` with a context string such as a field path
 * (`"primaries[1].surface[2]: "`). No-op when `err` is NULL.
 * @return err->code, or C2B_OK when err is NULL: so never `return` this call's value
 *         as the failing status; return the status you already have.
 */
c2b_status c2b_error_prefix(c2b_error *err, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/** Reset a record to C2B_OK with an empty message. NULL-safe. */
void c2b_error_clear(c2b_error *err);

/** Short name of a status code ("spec error", ...). Never NULL. */
const char *c2b_status_name(c2b_status code);

#ifdef __cplusplus
}
#endif
#endif
