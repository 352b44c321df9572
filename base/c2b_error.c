#include "c2b_error.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

c2b_status c2b_error_set(c2b_error *err, c2b_status code, const char *fmt, ...)
{
    if (err) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err->msg, sizeof err->msg, fmt, ap);
        va_end(ap);
        err->code = code;
    }
    return code;
}

c2b_status c2b_error_prefix(c2b_error *err, const char *fmt, ...)
{
    if (!err)
        return C2B_OK;
    char head[C2B_ERROR_MSG_LEN];
    va_list ap;
    va_start(ap, fmt);
    int hl = vsnprintf(head, sizeof head, fmt, ap);
    va_end(ap);
    if (hl < 0)
        return err->code;
    size_t h = (size_t)hl < sizeof head ? (size_t)hl : sizeof head - 1;
    size_t cap = sizeof err->msg - 1;
    err->msg[cap] = '\0';
    size_t tl = strlen(err->msg);
    if (h > cap)
        h = cap;
    if (tl > cap - h)
        tl = cap - h;
    memmove(err->msg + h, err->msg, tl);
    memcpy(err->msg, head, h);
    err->msg[h + tl] = '\0';
    return err->code;
}

void c2b_error_clear(c2b_error *err)
{
    if (err) {
        err->code = C2B_OK;
        err->msg[0] = '\0';
    }
}

const char *c2b_status_name(c2b_status code)
{
    switch (code) {
    case C2B_OK: return "ok";
    case C2B_ERR_ARG: return "invalid argument";
    case C2B_ERR_SPEC: return "spec error";
    case C2B_ERR_NUMERIC: return "numerical failure";
    case C2B_ERR_NOMEM: return "out of memory";
    case C2B_ERR_IO: return "i/o error";
    case C2B_ERR_LIMIT: return "limit exceeded";
    }
    return "unknown error";
}
