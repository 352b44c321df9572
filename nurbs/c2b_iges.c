/*
 * IGES 5.3 writer for one rational B-spline surface (entity 128).
 *
 * References: IGES 5.3 (US PRO/IPO-100, 1996): 2.2 file structure (fixed 80-column
 * records, sections S, G, D, P, T), 2.2.2 parameter types (integers, reals with a decimal
 * point, Hollerith strings nH...), 2.2.4 the Global section, 2.2.4.4 the Directory Entry,
 * 4.24 entity 128.
 *
 * The writer allocates nothing but the temporary file name. It makes two passes over the
 * Parameter Data: the first only counts records (the Directory Entry needs the count
 * before the section is written), the second writes them.
 */
#define _POSIX_C_SOURCE 200809L

#include "c2b_iges.h"

#include "c2b_atomic.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* Name and revision of this writer, written as the preprocessor version (Global field 6). */
#define IGES_PREPROCESSOR "C2Blend IGES writer 1"
/* Version flag 11 = IGES 5.3 (Global field 23). */
#define IGES_VERSION_FLAG 11
/* Data columns of a record: 72 in S, G, D and T; 64 in P (65 blank, 66-72 DE pointer). */
#define IGES_COLS 72
#define IGES_PCOLS 64
/* Longest number token: sign, 17 digits, point, 'E', exponent sign, 3 digits, delimiter. */
#define IGES_TOKEN_MAX 80

/* ---- unit names (IGES 5.3 table 3, Global fields 14 and 15) -------------------------- */

typedef struct iges_unit {
    const char *name;
    int flag;
} iges_unit;

static const iges_unit iges_units[] = {
    {"IN", 1},  {"INCH", 1}, {"MM", 2}, {"FT", 4},  {"MI", 5},   {"M", 6},
    {"KM", 7},  {"MIL", 8},  {"UM", 9}, {"CM", 10}, {"UIN", 11},
};

static const iges_unit *iges_find_unit(const char *name)
{
    for (size_t k = 0; k < sizeof iges_units / sizeof iges_units[0]; k++) {
        const char *a = iges_units[k].name, *b = name;
        while (*a && *b && *a == toupper((unsigned char)*b)) {
            a++;
            b++;
        }
        if (*a == '\0' && *b == '\0')
            return &iges_units[k];
    }
    return NULL;
}

/* ---- record output -------------------------------------------------------------------- */

/* One section being written (or, with f == NULL, only counted). */
typedef struct iges_out {
    FILE *f;         /* NULL: count records only */
    char sect;       /* 'S', 'G', 'D', 'P' or 'T' */
    int width;       /* data columns */
    long de;         /* P: sequence number of the entity's first DE record */
    char data[IGES_COLS + 1];
    int col;         /* columns of data used in the current record */
    long nrec;       /* records finished in this section */
    int write_errno; /* first write failure (0: none) */
} iges_out;

static void out_begin(iges_out *o, FILE *f, char sect, int width, long de)
{
    o->f = f;
    o->sect = sect;
    o->width = width;
    o->de = de;
    o->col = 0;
    o->nrec = 0;
    o->write_errno = 0;
}

/* v (0 <= v < 10^w) right-justified in the w columns at dst, blank-filled. */
static void put_field(char *dst, int w, long v)
{
    memset(dst, ' ', (size_t)w);
    int k = w - 1;
    do {
        dst[k--] = (char)('0' + v % 10);
        v /= 10;
    } while (v > 0 && k >= 0);
}

/* Finish the current record: pad the data, add DE pointer (P), letter and sequence. */
static void out_record(iges_out *o)
{
    char rec[81];
    o->nrec++;
    if (o->f == NULL || o->write_errno != 0) {
        o->col = 0;
        return;
    }
    memset(rec, ' ', 80);
    memcpy(rec, o->data, (size_t)o->col);
    if (o->sect == 'P')
        put_field(rec + 65, 7, o->de);
    rec[72] = o->sect;
    put_field(rec + 73, 7, o->nrec);
    rec[80] = '\n';
    errno = 0;
    if (fwrite(rec, 1, 81, o->f) != 81)
        o->write_errno = errno ? errno : EIO;
    o->col = 0;
}

/* Append a token (its delimiter included); start a new record if it does not fit. */
static void out_token(iges_out *o, const char *tok)
{
    int len = (int)strlen(tok);
    if (o->col + len > o->width)
        out_record(o);
    memcpy(o->data + o->col, tok, (size_t)len);
    o->col += len;
}

/* Close the section: flush a partly filled record. */
static void out_end(iges_out *o)
{
    if (o->col > 0)
        out_record(o);
}

/* A whole record of text (S section, D entries, T), cut at the data width. */
static void out_line(iges_out *o, const char *text)
{
    size_t len = strlen(text);
    if (len > (size_t)o->width)
        len = (size_t)o->width;
    memcpy(o->data, text, len);
    o->col = (int)len;
    out_record(o);
}

/* ---- tokens --------------------------------------------------------------------------- */

/*
 * Shortest decimal form of x (15 to 17 significant digits) that reads back as x, with a
 * decimal point so that readers take it as real, 'E' exponent, delimiter appended.
 * Independent of LC_NUMERIC: the locale's decimal separator is replaced by '.'.
 */
static void fmt_real(char *buf, double x, char delim)
{
    char raw[48];
    int prec;
    for (prec = 15; prec < 17; prec++) {
        snprintf(raw, sizeof raw, "%.*G", prec, x);
        if (strtod(raw, NULL) == x)
            break;
    }
    if (prec == 17)
        snprintf(raw, sizeof raw, "%.17G", x);

    /* copy, normalising the decimal separator and adding ".0" where no point exists */
    char *o = buf;
    const char *r = raw;
    int seen_point = 0;
    if (*r == '-' || *r == '+')
        *o++ = *r++;
    while (*r && *r != 'E') {
        if (isdigit((unsigned char)*r)) {
            *o++ = *r++;
        } else { /* decimal separator, possibly multibyte in an exotic locale */
            while (*r && !isdigit((unsigned char)*r) && *r != 'E')
                r++;
            *o++ = '.';
            seen_point = 1;
        }
    }
    if (!seen_point) {
        *o++ = '.';
        *o++ = '0';
    }
    while (*r) /* exponent: E, sign, digits */
        *o++ = *r++;
    *o++ = delim;
    *o = '\0';
}

static void emit_real(iges_out *o, double x, char delim)
{
    char tok[IGES_TOKEN_MAX];
    fmt_real(tok, x, delim);
    out_token(o, tok);
}

static void emit_int(iges_out *o, long v, char delim)
{
    char tok[IGES_TOKEN_MAX];
    snprintf(tok, sizeof tok, "%ld%c", v, delim);
    out_token(o, tok);
}

/* Hollerith string nH..., printable ASCII only, truncated so the token fits one record.
 * An empty string is written as an empty (default) field. */
static void emit_string(iges_out *o, const char *s, size_t len, char delim)
{
    char tok[IGES_COLS + 1];
    size_t room = (size_t)o->width - 1 /* delim */ - 1 /* H */ - 2 /* count, <= 99 */;
    if (len > room)
        len = room;
    if (len == 0) {
        tok[0] = delim;
        tok[1] = '\0';
        out_token(o, tok);
        return;
    }
    int n = snprintf(tok, sizeof tok, "%zuH", len);
    for (size_t k = 0; k < len; k++) {
        unsigned char c = (unsigned char)s[k];
        tok[n + (int)k] = (c >= 0x20 && c < 0x7f) ? (char)c : '_';
    }
    tok[n + (int)len] = delim;
    tok[n + (int)len + 1] = '\0';
    out_token(o, tok);
}

/* ---- the surface in IGES form ------------------------------------------------------- */

/* One parametric direction of the (unwrapped) pole net. */
typedef struct iges_dir {
    int p;               /* degree M */
    int n;               /* distinct poles */
    int nout;            /* poles written: n, or n + p when periodic (K = nout - 1) */
    int periodic;
    int closed;
    int nknots;          /* nout + p + 1 */
    const double *knots;
    double t0, t1;       /* parameter range */
} iges_dir;

typedef struct iges_surf {
    const c2b_nurbs_surface *s;
    iges_dir d[2];
    int polynomial;      /* all weights equal */
    double maxcoord;     /* max |pole coordinate| */
    double resolution;
} iges_surf;

static void surf_pole(const iges_surf *g, int i, int j, double *xyzw)
{
    c2b_nurbs_surface_pole(g->s, i % g->d[0].n, j % g->d[1].n, xyzw);
}

/* Closed in direction dir when clamped at both ends and the first and last pole rows
 * coincide (same weights, points within the resolution); periodic implies closed. */
static int surf_closed(const iges_surf *g, int dir)
{
    const iges_dir *d = &g->d[dir];
    if (d->periodic)
        return 1;
    for (int k = 1; k <= d->p; k++)
        if (d->knots[k] != d->knots[0] || d->knots[d->nknots - 1 - k] != d->knots[d->nknots - 1])
            return 0;
    int other = g->d[1 - dir].n;
    for (int k = 0; k < other; k++) {
        double a[4], b[4];
        if (dir == 0) {
            surf_pole(g, 0, k, a);
            surf_pole(g, d->n - 1, k, b);
        } else {
            surf_pole(g, k, 0, a);
            surf_pole(g, k, d->n - 1, b);
        }
        double dist = sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                           (a[2] - b[2]) * (a[2] - b[2]));
        if (a[3] != b[3] || !(dist <= g->resolution))
            return 0;
    }
    return 1;
}

static c2b_status surf_setup(iges_surf *g, const c2b_nurbs_surface *s, c2b_error *err)
{
    static const char *const knot_name[2] = {"knots_u", "knots_v"};
    double dom[4];
    g->s = s;
    c2b_nurbs_surface_domain(s, dom);
    for (int dir = 0; dir < 2; dir++) {
        iges_dir *d = &g->d[dir];
        d->p = c2b_nurbs_surface_degree(s, dir);
        d->n = c2b_nurbs_surface_npoles(s, dir);
        d->periodic = c2b_nurbs_surface_periodic(s, dir) != 0;
        d->nout = d->n + (d->periodic ? d->p : 0);
        d->nknots = c2b_nurbs_surface_nknots(s, dir);
        d->knots = c2b_nurbs_surface_knots(s, dir);
        d->t0 = dom[2 * dir];
        d->t1 = dom[2 * dir + 1];
        if (d->p < 1 || d->n < (d->periodic ? 1 : d->p + 1) || d->knots == NULL || d->nknots != d->nout + d->p + 1)
            return c2b_error_set(err, C2B_ERR_ARG,
                                 "iges: %s: degree %d, %d poles%s and %d knots are inconsistent",
                                 knot_name[dir], d->p, d->n, d->periodic ? " (periodic)" : "",
                                 d->nknots);
        for (int k = 0; k < d->nknots; k++)
            if (!isfinite(d->knots[k]))
                return c2b_error_set(err, C2B_ERR_ARG, "iges: %s[%d] is not finite",
                                     knot_name[dir], k);
        if (!isfinite(d->t0) || !isfinite(d->t1))
            return c2b_error_set(err, C2B_ERR_ARG, "iges: %s: domain is not finite",
                                 knot_name[dir]);
    }

    double w0 = 0.0;
    g->polynomial = 1;
    g->maxcoord = 0.0;
    for (int i = 0; i < g->d[0].n; i++)
        for (int j = 0; j < g->d[1].n; j++) {
            double q[4];
            c2b_nurbs_surface_pole(s, i, j, q);
            for (int c = 0; c < 4; c++)
                if (!isfinite(q[c]))
                    return c2b_error_set(err, C2B_ERR_ARG,
                                         "iges: poles[%d][%d]: %s is not finite", i, j,
                                         c == 3 ? "weight" : "coordinate");
            if (!(q[3] > 0.0))
                return c2b_error_set(err, C2B_ERR_ARG,
                                     "iges: poles[%d][%d]: weight must be positive", i, j);
            if (i == 0 && j == 0)
                w0 = q[3];
            else if (q[3] != w0)
                g->polynomial = 0;
            for (int c = 0; c < 3; c++)
                if (fabs(q[c]) > g->maxcoord)
                    g->maxcoord = fabs(q[c]);
        }
    g->resolution = C2B_IGES_RESOLUTION_REL * g->maxcoord;
    if (!(g->resolution > C2B_IGES_RESOLUTION_MIN))
        g->resolution = C2B_IGES_RESOLUTION_MIN;
    g->d[0].closed = surf_closed(g, 0);
    g->d[1].closed = surf_closed(g, 1);
    return C2B_OK;
}

/* Parameter Data of entity 128 (IGES 5.3, 4.24): u index fastest in weights and poles. */
static void emit_params(iges_out *o, const iges_surf *g)
{
    const iges_dir *u = &g->d[0], *v = &g->d[1];
    emit_int(o, 128, ',');
    emit_int(o, u->nout - 1, ','); /* K1 */
    emit_int(o, v->nout - 1, ','); /* K2 */
    emit_int(o, u->p, ',');        /* M1 */
    emit_int(o, v->p, ',');        /* M2 */
    emit_int(o, u->closed, ',');   /* PROP1 */
    emit_int(o, v->closed, ',');   /* PROP2 */
    emit_int(o, g->polynomial, ','); /* PROP3 */
    emit_int(o, u->periodic, ','); /* PROP4 */
    emit_int(o, v->periodic, ','); /* PROP5 */
    for (int k = 0; k < u->nknots; k++)
        emit_real(o, u->knots[k], ',');
    for (int k = 0; k < v->nknots; k++)
        emit_real(o, v->knots[k], ',');
    for (int j = 0; j < v->nout; j++)
        for (int i = 0; i < u->nout; i++) {
            double q[4];
            surf_pole(g, i, j, q);
            emit_real(o, q[3], ',');
        }
    for (int j = 0; j < v->nout; j++)
        for (int i = 0; i < u->nout; i++) {
            double q[4];
            surf_pole(g, i, j, q);
            emit_real(o, q[0], ',');
            emit_real(o, q[1], ',');
            emit_real(o, q[2], ',');
        }
    emit_real(o, u->t0, ',');
    emit_real(o, u->t1, ',');
    emit_real(o, v->t0, ',');
    emit_real(o, v->t1, ';');
}

/* Global section (IGES 5.3, 2.2.4): fields 1 to 25. */
static void emit_global(iges_out *o, const iges_surf *g, const char *fname,
                        const iges_unit *unit, const char *date)
{
    size_t flen = strlen(fname);
    const char *dot = strrchr(fname, '.');
    size_t plen = (dot != NULL && dot != fname) ? (size_t)(dot - fname) : flen;

    emit_string(o, ",", 1, ',');                       /* 1 parameter delimiter */
    emit_string(o, ";", 1, ',');                       /* 2 record delimiter */
    emit_string(o, fname, plen, ',');                  /* 3 product id (sender) */
    emit_string(o, fname, flen, ',');                  /* 4 file name */
    emit_string(o, "C2Blend", 7, ',');                 /* 5 native system id */
    emit_string(o, IGES_PREPROCESSOR, strlen(IGES_PREPROCESSOR), ','); /* 6 */
    emit_int(o, 32, ',');                              /* 7 integer bits */
    emit_int(o, 38, ',');                              /* 8 single precision magnitude */
    emit_int(o, 6, ',');                               /* 9 single precision digits */
    emit_int(o, 308, ',');                             /* 10 double precision magnitude */
    emit_int(o, 15, ',');                              /* 11 double precision digits */
    emit_string(o, fname, plen, ',');                  /* 12 product id (receiver) */
    emit_real(o, 1.0, ',');                            /* 13 model space scale */
    emit_int(o, unit->flag, ',');                      /* 14 unit flag */
    emit_string(o, unit->name, strlen(unit->name), ','); /* 15 unit name */
    emit_int(o, 1, ',');                               /* 16 line weight gradations */
    emit_real(o, 1.0, ',');                            /* 17 max line width */
    emit_string(o, date, strlen(date), ',');           /* 18 date of file */
    emit_real(o, g->resolution, ',');                  /* 19 minimum resolution */
    emit_real(o, g->maxcoord, ',');                    /* 20 approximate max coordinate */
    emit_string(o, "", 0, ',');                        /* 21 author */
    emit_string(o, "", 0, ',');                        /* 22 organisation */
    emit_int(o, IGES_VERSION_FLAG, ',');               /* 23 version flag */
    emit_int(o, 0, ',');                               /* 24 drafting standard */
    emit_string(o, date, strlen(date), ';');           /* 25 model creation date */
}

/* Directory Entry (IGES 5.3, 2.2.4.4): two records of ten 8-column fields. */
static void emit_directory(iges_out *o, long pstart, long pcount)
{
    char rec[IGES_COLS + 1];
    /* type, parameter pointer, structure, line font, level, view, transform, label
     * display, status (visible, independent, geometry, top-down) */
    snprintf(rec, sizeof rec, "%8d%8ld%8d%8d%8d%8d%8d%8d%8s", 128, pstart, 0, 0, 0, 0, 0, 0,
             "00000000");
    out_line(o, rec);
    /* type, line weight, colour, parameter record count, form, reserved x2, label,
     * subscript */
    snprintf(rec, sizeof rec, "%8d%8d%8d%8ld%8d%8s%8s%8s%8d", 128, 0, 0, pcount, 0, "", "",
             "NURBSSRF", 0);
    out_line(o, rec);
}

/* ---- file handling -------------------------------------------------------------------- */

/* C2B_ERR_IO naming the target, the temporary file when there is one, and the system
 * error. */
static c2b_status io_error(c2b_error *err, const char *what, const char *path, const char *tmp,
                           int errnum)
{
    char msg[256];
    if (strerror_r(errnum, msg, sizeof msg) != 0)
        snprintf(msg, sizeof msg, "error %d", errnum);
    if (tmp != NULL)
        return c2b_error_set(err, C2B_ERR_IO, "iges: %s '%s' (temporary file '%s'): %s", what,
                             path, tmp, msg);
    return c2b_error_set(err, C2B_ERR_IO, "iges: %s '%s': %s", what, path, msg);
}

/* Write every section to f. Returns 0 or the errno of the first failed write. */
static int write_sections(FILE *f, const iges_surf *g, const char *fname, const iges_unit *unit,
                          const char *date, long pcount, long *counts)
{
    iges_out o;
    int e = 0;

    out_begin(&o, f, 'S', IGES_COLS, 0);
    out_line(&o, "C2Blend NURBS surface: IGES 5.3 entity 128, rational B-spline surface");
    counts[0] = o.nrec;
    e = e ? e : o.write_errno;

    out_begin(&o, f, 'G', IGES_COLS, 0);
    emit_global(&o, g, fname, unit, date);
    out_end(&o);
    counts[1] = o.nrec;
    e = e ? e : o.write_errno;

    out_begin(&o, f, 'D', IGES_COLS, 0);
    emit_directory(&o, 1, pcount);
    counts[2] = o.nrec;
    e = e ? e : o.write_errno;

    out_begin(&o, f, 'P', IGES_PCOLS, 1);
    emit_params(&o, g);
    out_end(&o);
    counts[3] = o.nrec;
    e = e ? e : o.write_errno;

    char rec[IGES_COLS + 1];
    snprintf(rec, sizeof rec, "S%7ldG%7ldD%7ldP%7ld", counts[0], counts[1], counts[2],
             counts[3]);
    out_begin(&o, f, 'T', IGES_COLS, 0);
    out_line(&o, rec);
    e = e ? e : o.write_errno;
    return e;
}

c2b_status c2b_iges_write_surface(const c2b_nurbs_surface *s, const char *path,
                                  const char *units, c2b_error *err)
{
    if (s == NULL)
        return c2b_error_set(err, C2B_ERR_ARG, "iges: surface is NULL");
    if (path == NULL || path[0] == '\0')
        return c2b_error_set(err, C2B_ERR_ARG, "iges: output path is %s",
                             path == NULL ? "NULL" : "empty");
    const iges_unit *unit = iges_find_unit(units != NULL ? units : "MM");
    if (unit == NULL)
        return c2b_error_set(err, C2B_ERR_ARG,
                             "iges: units: unknown unit name '%s' (expected IN, INCH, MM, FT, "
                             "MI, M, KM, MIL, UM, CM or UIN)",
                             units);

    iges_surf g;
    c2b_status st = surf_setup(&g, s, err);
    if (st != C2B_OK)
        return st;

    /* A pole takes at least 16 columns ("1.0," for its weight and each coordinate), so
     * 4 poles per record at most: reject hopeless sizes before the counting pass. */
    long long npoles = (long long)g.d[0].nout * g.d[1].nout;
    if (npoles / 4 > C2B_IGES_MAX_RECORDS)
        return c2b_error_set(err, C2B_ERR_LIMIT,
                             "iges: %d x %d poles exceed the IGES limit of %ld parameter "
                             "records",
                             g.d[0].nout, g.d[1].nout, C2B_IGES_MAX_RECORDS);

    /* first pass: count Parameter Data records */
    iges_out count;
    out_begin(&count, NULL, 'P', IGES_PCOLS, 1);
    emit_params(&count, &g);
    out_end(&count);
    if (count.nrec > C2B_IGES_MAX_RECORDS)
        return c2b_error_set(err, C2B_ERR_LIMIT,
                             "iges: %d x %d poles need %ld parameter records, more than the "
                             "IGES limit of %ld",
                             g.d[0].nout, g.d[1].nout, count.nrec, C2B_IGES_MAX_RECORDS);

    const char *fname = strrchr(path, '/');
    fname = fname != NULL ? fname + 1 : path;

    char date[16];
    {
        time_t now = time(NULL);
        struct tm tm;
        if (now == (time_t)-1 || gmtime_r(&now, &tm) == NULL)
            memset(&tm, 0, sizeof tm);
        if (strftime(date, sizeof date, "%Y%m%d.%H%M%S", &tm) != 15)
            snprintf(date, sizeof date, "%s", "19700101.000000");
    }

    c2b_atomic_file f;
    st = c2b_atomic_open(&f, path, err);
    if (st != C2B_OK) {
        c2b_error_prefix(err, "iges: ");
        return st;
    }
    long counts[4];
    int e = write_sections(f.fp, &g, fname, unit, date, count.nrec, counts);
    if (e != 0) {
        c2b_atomic_abort(&f);
        return io_error(err, "cannot write", path, NULL, e);
    }
    st = c2b_atomic_commit(&f, err);
    if (st != C2B_OK)
        c2b_error_prefix(err, "iges: ");
    return st;
}
