/**
 * @file c2blend_module.c
 * The CPython extension module `c2blend`: PDE blend surfaces, their B-spline fit and
 * their continuity report, for Python and FreeCAD.
 *
 * Structure after CPython's Modules/xxlimited.c:
 *  - all state lives in the module state struct (exception classes, the Blend type, the
 *    cached numpy.frombuffer); there is no global mutable state in this file;
 *  - multi-phase initialisation (PEP 489): PyInit_c2blend() only returns the definition,
 *    c2blend_exec() fills the module;
 *  - the Blend type is a heap type made with PyType_FromModuleAndSpec(), so its methods
 *    reach the module state through PyType_GetModuleByDef().
 *
 * Arrays go in through the buffer protocol (format "d", any stride, released on every
 * path) or as sequences of numbers, and come out as numpy.ndarray (numpy.frombuffer of a
 * bytearray filled in C) when numpy imports, else as a shaped memoryview. The module is
 * not compiled against NumPy.
 *
 * Threads. Evaluation and fitting run with the GIL released. Everything that can reach
 * libmatheval's parser (a global yacc parser: spec parsing, symbolic derivatives made on
 * first use) or FFTW's planner (not thread-safe: blend creation, set_time) runs with the
 * GIL held, so those calls are serialised across all Blend objects. Each Blend also has
 * its own lock, taken around every use of its kernel objects, because the kernel's blend
 * must not be used from two threads at once (README, "C API").
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <pythread.h>

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "c2b_blend.h"
#include "c2b_check.h"
#include "c2b_error.h"
#include "c2b_fit.h"
#include "c2b_nurbs.h"
#include "c2b_nurbs_json.h"
#include "c2b_operator.h"
#include "c2b_spec.h"

#ifndef C2B_VERSION
#define C2B_VERSION "unknown"
#endif

/* Names of the boundary data rows d^k S/du^k, as in the CLI's fit output. */
static const char *const c2b_row_names[C2B_MAX_N] = {"S", "S_u", "S_uu", "S_uuu"};

/* ---- module state ------------------------------------------------------------------ */

/** Per-module state (xxlimited.c style). */
typedef struct {
    PyObject *Error;          /**< c2blend.Error(Exception) */
    PyObject *SpecError;      /**< c2blend.SpecError(Error): C2B_ERR_SPEC, _ARG, _LIMIT */
    PyObject *NumericalError; /**< c2blend.NumericalError(Error): C2B_ERR_NUMERIC */
    PyObject *BlendType;      /**< the heap type c2blend.Blend */
    PyObject *frombuffer;     /**< numpy.frombuffer; NULL: not looked up yet; None: no numpy */
} c2blend_state;

static struct PyModuleDef c2blend_module;

/** The state of module m. */
static c2blend_state *state_of_module(PyObject *m)
{
    return (c2blend_state *)PyModule_GetState(m);
}

/** Module state reached from a Blend instance or the Blend type (NULL with an exception). */
static c2blend_state *state_of_type(PyTypeObject *tp)
{
    PyObject *m = PyType_GetModuleByDef(tp, &c2blend_module);
    return m ? state_of_module(m) : NULL;
}

/* ---- errors ------------------------------------------------------------------------ */

/**
 * Raise the Python exception for a kernel error: SpecError (SPEC, ARG, LIMIT),
 * NumericalError (NUMERIC), MemoryError (NOMEM), OSError (IO), else Error. The message
 * is the kernel's text verbatim; the instance gets `.status` (the kernel's code).
 * Always returns NULL.
 */
static PyObject *raise_kernel(c2blend_state *st, const c2b_error *err)
{
    PyObject *cls;
    switch (err->code) {
    case C2B_ERR_SPEC:
    case C2B_ERR_ARG:
    case C2B_ERR_LIMIT: cls = st->SpecError; break;
    case C2B_ERR_NUMERIC: cls = st->NumericalError; break;
    case C2B_ERR_NOMEM: cls = PyExc_MemoryError; break;
    case C2B_ERR_IO: cls = PyExc_OSError; break;
    default: cls = st->Error; break;
    }
    const char *text = err->msg[0] ? err->msg : c2b_status_name(err->code);
    PyObject *msg = PyUnicode_DecodeUTF8(text, (Py_ssize_t)strnlen(text, C2B_ERROR_MSG_LEN),
                                         "replace");
    if (!msg)
        return NULL;
    PyObject *exc = PyObject_CallOneArg(cls, msg);
    Py_DECREF(msg);
    if (!exc)
        return NULL;
    PyObject *code = PyLong_FromLong((long)err->code);
    if (!code || PyObject_SetAttrString(exc, "status", code) < 0) {
        Py_XDECREF(code);
        Py_DECREF(exc);
        return NULL;
    }
    Py_DECREF(code);
    PyErr_SetObject((PyObject *)Py_TYPE(exc), exc);
    Py_DECREF(exc);
    return NULL;
}

/** Raise a module error of class cls with a formatted message and `.status` = code. */
static PyObject *raise_status(c2blend_state *st, c2b_status code, const char *fmt, ...)
{
    c2b_error err;
    va_list ap;
    va_start(ap, fmt);
    err.code = code;
    PyOS_vsnprintf(err.msg, sizeof err.msg, fmt, ap);
    va_end(ap);
    return raise_kernel(st, &err);
}

/* ---- numbers and arrays in ------------------------------------------------------------ */

/** Type name of o for messages. */
static const char *tname(PyObject *o)
{
    return Py_TYPE(o)->tp_name;
}

/**
 * An optional finite number: None gives *has = 0. TypeError/ValueError name
 * `method: name`. @return 0, or -1 with an exception set.
 */
static int parse_opt_number(PyObject *o, const char *method, const char *name, int *has, double *x)
{
    *has = 0;
    if (o == NULL || o == Py_None)
        return 0;
    if (!PyFloat_Check(o) && !PyLong_Check(o) && !PyNumber_Check(o)) {
        PyErr_Format(PyExc_TypeError, "%s: %s must be a number or None (got %s)", method, name,
                     tname(o));
        return -1;
    }
    double d = PyFloat_AsDouble(o);
    if (d == -1.0 && PyErr_Occurred()) {
        if (PyErr_ExceptionMatches(PyExc_TypeError)) {
            PyErr_Clear();
            PyErr_Format(PyExc_TypeError, "%s: %s must be a number or None (got %s)", method,
                         name, tname(o));
        }
        return -1;
    }
    if (!isfinite(d)) {
        PyErr_Format(PyExc_ValueError, "%s: %s is not finite", method, name);
        return -1;
    }
    *has = 1;
    *x = d;
    return 0;
}

/** A required positive finite number (tolerances). @return 0 or -1 with ValueError. */
static int check_positive(double x, const char *method, const char *name)
{
    if (!(x > 0) || !isfinite(x)) {
        char buf[32];
        PyOS_snprintf(buf, sizeof buf, "%.17g", x);
        PyErr_Format(PyExc_ValueError, "%s: %s must be a positive finite number (got %s)", method,
                     name, buf);
        return -1;
    }
    return 0;
}

/** A parameter array converted from Python: n contiguous doubles owned here. */
typedef struct {
    double *data;   /**< PyMem buffer, or &one for a scalar */
    Py_ssize_t n;
    int scalar;     /**< given as a Python number (n = 1) */
    double one;
} dvec;

/** An empty dvec. */
static void dvec_init(dvec *d)
{
    d->data = NULL;
    d->n = 0;
    d->scalar = 0;
    d->one = 0.0;
}

/** Free a dvec's buffer (NULL-safe, idempotent). */
static void dvec_free(dvec *d)
{
    if (d->data && d->data != &d->one)
        PyMem_Free(d->data);
    d->data = NULL;
}

/** 1 when a buffer's struct format is a native double. */
static int format_is_double(const char *f)
{
    static const union {
        uint16_t u;
        unsigned char c[2];
    } probe = {1};
    if (f == NULL)
        return 0; /* unsigned bytes */
    if (f[0] == '@' || f[0] == '=')
        f++;
    else if (f[0] == '<' && probe.c[0] == 1)
        f++;
    else if ((f[0] == '>' || f[0] == '!') && probe.c[0] == 0)
        f++;
    return f[0] == 'd' && f[1] == '\0';
}

/** Check that every value is finite, naming the first bad index. */
static int dvec_check_finite(const dvec *d, const char *method, const char *name)
{
    for (Py_ssize_t i = 0; i < d->n; i++)
        if (!isfinite(d->data[i])) {
            if (d->scalar)
                PyErr_Format(PyExc_ValueError, "%s: %s is not finite", method, name);
            else
                PyErr_Format(PyExc_ValueError, "%s: %s[%zd] is not finite", method, name, i);
            return -1;
        }
    return 0;
}

/**
 * Convert o to doubles: a Python float or int (scalar, n = 1), an object with the buffer
 * protocol holding doubles (format "d", 0 or 1 dimensions, any stride), or a sequence of
 * numbers. Values must be finite. @return 0, or -1 with TypeError/ValueError naming
 * `method: name`.
 */
static int dvec_from(PyObject *o, const char *method, const char *name, dvec *d)
{
    dvec_init(d);
    if (PyFloat_Check(o) || PyLong_Check(o)) {
        d->one = PyFloat_AsDouble(o);
        if (d->one == -1.0 && PyErr_Occurred())
            return -1;
        d->data = &d->one;
        d->n = 1;
        d->scalar = 1;
        return dvec_check_finite(d, method, name);
    }
    if (PyObject_CheckBuffer(o)) {
        Py_buffer view;
        if (PyObject_GetBuffer(o, &view, PyBUF_RECORDS_RO) < 0)
            return -1;
        int rc = -1;
        if (!format_is_double(view.format) || view.itemsize != (Py_ssize_t)sizeof(double)) {
            PyErr_Format(PyExc_TypeError,
                         "%s: %s is a buffer of format '%s'; buffers must hold doubles "
                         "(format 'd'), e.g. numpy.asarray(%s, dtype=float)",
                         method, name, view.format ? view.format : "B", name);
        } else if (view.ndim > 1) {
            PyErr_Format(PyExc_ValueError, "%s: %s must be one-dimensional (got %d dimensions)",
                         method, name, view.ndim);
        } else {
            Py_ssize_t n = view.ndim == 0 ? 1 : view.shape[0];
            Py_ssize_t stride = view.ndim == 0 || !view.strides ? (Py_ssize_t)sizeof(double)
                                                                : view.strides[0];
            d->data = PyMem_Malloc((size_t)(n > 0 ? n : 1) * sizeof(double));
            if (!d->data) {
                PyErr_NoMemory();
            } else {
                for (Py_ssize_t i = 0; i < n; i++)
                    memcpy(d->data + i, (const char *)view.buf + i * stride, sizeof(double));
                d->n = n;
                rc = dvec_check_finite(d, method, name);
            }
        }
        PyBuffer_Release(&view);
        return rc;
    }
    if (PyUnicode_Check(o) || o == Py_None || !PySequence_Check(o)) {
        PyErr_Format(PyExc_TypeError,
                     "%s: %s must be a float, a sequence of floats or a buffer of doubles (got %s)",
                     method, name, tname(o));
        return -1;
    }
    PyObject *seq = PySequence_Fast(o, "");
    if (!seq)
        return -1;
    Py_ssize_t n = PySequence_Fast_GET_SIZE(seq);
    d->data = PyMem_Malloc((size_t)(n > 0 ? n : 1) * sizeof(double));
    if (!d->data) {
        Py_DECREF(seq);
        PyErr_NoMemory();
        return -1;
    }
    PyObject **items = PySequence_Fast_ITEMS(seq);
    for (Py_ssize_t i = 0; i < n; i++) {
        PyObject *it = items[i];
        double x = -1.0;
        if (PyFloat_Check(it) || PyLong_Check(it) || PyNumber_Check(it))
            x = PyFloat_AsDouble(it);
        else
            PyErr_SetString(PyExc_TypeError, "");
        if (x == -1.0 && PyErr_Occurred()) {
            if (PyErr_ExceptionMatches(PyExc_TypeError)) {
                PyErr_Clear();
                PyErr_Format(PyExc_TypeError, "%s: %s[%zd] must be a number (got %s)", method,
                             name, i, tname(it));
            }
            Py_DECREF(seq);
            dvec_free(d);
            return -1;
        }
        d->data[i] = x;
    }
    Py_DECREF(seq);
    d->n = n;
    if (dvec_check_finite(d, method, name) < 0) {
        dvec_free(d);
        return -1;
    }
    return 0;
}

/** Repeat a scalar n times (n >= 1). @return 0 or -1 with MemoryError. */
static int dvec_broadcast(dvec *d, Py_ssize_t n)
{
    double *x = PyMem_Malloc((size_t)n * sizeof(double));
    if (!x) {
        PyErr_NoMemory();
        return -1;
    }
    for (Py_ssize_t i = 0; i < n; i++)
        x[i] = d->one;
    d->data = x;
    d->n = n;
    return 0;
}

/* ---- arrays out ------------------------------------------------------------------------- */

/** numpy.frombuffer, looked up once per module; Py_None when numpy does not import.
 *  Borrowed reference, or NULL with an exception (other than ImportError). */
static PyObject *get_frombuffer(c2blend_state *st)
{
    if (st->frombuffer)
        return st->frombuffer;
    PyObject *np = PyImport_ImportModule("numpy");
    if (!np) {
        if (!PyErr_ExceptionMatches(PyExc_ImportError))
            return NULL;
        PyErr_Clear();
        st->frombuffer = Py_NewRef(Py_None);
        return st->frombuffer;
    }
    st->frombuffer = PyObject_GetAttrString(np, "frombuffer");
    Py_DECREF(np);
    return st->frombuffer;
}

/**
 * Wrap a bytearray of doubles (reference stolen) as an array of the given shape:
 * numpy.frombuffer(ba, "float64").reshape(shape), or memoryview(ba).cast("d", shape)
 * without numpy (a memoryview cannot have a zero in its shape: empty results are then
 * one-dimensional).
 */
static PyObject *wrap_array(c2blend_state *st, PyObject *ba, int ndim, const Py_ssize_t *shape)
{
    PyObject *res = NULL, *tuple = PyTuple_New(ndim);
    int empty = 0;
    if (!tuple)
        goto done;
    for (int i = 0; i < ndim; i++) {
        PyObject *x = PyLong_FromSsize_t(shape[i]);
        if (!x)
            goto done;
        PyTuple_SET_ITEM(tuple, i, x);
        empty |= shape[i] == 0;
    }
    PyObject *fb = get_frombuffer(st);
    if (!fb)
        goto done;
    if (fb != Py_None) {
        PyObject *flat = PyObject_CallFunction(fb, "Os", ba, "float64");
        if (flat) {
            res = PyObject_CallMethod(flat, "reshape", "O", tuple);
            Py_DECREF(flat);
        }
    } else {
        PyObject *mv = PyMemoryView_FromObject(ba);
        if (mv) {
            res = empty ? PyObject_CallMethod(mv, "cast", "s", "d")
                        : PyObject_CallMethod(mv, "cast", "sO", "d", tuple);
            Py_DECREF(mv);
        }
    }
done:
    Py_XDECREF(tuple);
    Py_DECREF(ba);
    return res;
}

/** A new bytearray for n doubles, or NULL with an exception (overflow: MemoryError). */
static PyObject *new_doubles(size_t n, double **data)
{
    if (n > (size_t)PY_SSIZE_T_MAX / sizeof(double)) {
        PyErr_NoMemory();
        return NULL;
    }
    PyObject *ba = PyByteArray_FromStringAndSize(NULL, (Py_ssize_t)(n * sizeof(double)));
    if (ba)
        *data = (double *)(void *)PyByteArray_AS_STRING(ba);
    return ba;
}

/* ---- the Blend type ------------------------------------------------------------------- */

/** A blend with the spec it was made from (the spec owns the data the blend refers to). */
typedef struct {
    PyObject_HEAD
    c2b_spec *spec;
    c2b_blend *blend;
    PyThread_type_lock lock; /**< serialises every use of spec and blend */
} BlendObject;

/** Take the object's lock; waits with the GIL released when another thread holds it. */
static void blend_lock(BlendObject *self)
{
    if (!PyThread_acquire_lock(self->lock, NOWAIT_LOCK)) {
        Py_BEGIN_ALLOW_THREADS
        PyThread_acquire_lock(self->lock, WAIT_LOCK);
        Py_END_ALLOW_THREADS
    }
}

/** Release the object's lock. */
static void blend_unlock(BlendObject *self)
{
    PyThread_release_lock(self->lock);
}

/**
 * Create a Blend of type tp from JSON text (text, len) or, when path is not NULL, from a
 * file; at `time` when has_time. The GIL stays held: spec parsing reaches libmatheval's
 * global parser and blend creation FFTW's planner.
 */
static PyObject *blend_make(PyTypeObject *tp, const char *text, Py_ssize_t len, const char *path,
                            int has_time, double time)
{
    c2blend_state *st = state_of_type(tp);
    if (!st)
        return NULL;
    c2b_error err;
    c2b_error_clear(&err);
    c2b_spec *spec = NULL;
    c2b_blend *blend = NULL;
    c2b_status s = path ? c2b_spec_load(path, &spec, &err)
                        : c2b_spec_parse(text, (size_t)len, &spec, &err);
    /* A Blend is the exact closed form: it fits, checks and moves in time. The papers'
     * approximate solvers (docs/APPROX.md) are for comparison, through the CLI. */
    if (!s && c2b_spec_solver_settings(spec).kind != C2B_SOLVER_EXACT)
        s = c2b_error_set(&err, C2B_ERR_SPEC,
                          "solver: the approximate solvers (thesis-approx, pseudo-navier) are not "
                          "available in the Python module, which fits and checks exact blends; "
                          "remove \"solver\" for the closed form, or evaluate them with the CLI: "
                          "c2blend eval SPEC");
    if (!s) {
        c2b_problem pb = *c2b_spec_problem(spec);
        if (has_time)
            pb.time = time;
        s = c2b_blend_create(&pb, &blend, &err);
    }
    if (s) {
        c2b_spec_destroy(spec);
        return raise_kernel(st, &err);
    }
    allocfunc alloc = (allocfunc)PyType_GetSlot(tp, Py_tp_alloc);
    BlendObject *self = (BlendObject *)alloc(tp, 0);
    if (!self) {
        c2b_blend_destroy(blend);
        c2b_spec_destroy(spec);
        return NULL;
    }
    self->spec = spec;
    self->blend = blend;
    self->lock = PyThread_allocate_lock();
    if (!self->lock) {
        Py_DECREF(self);
        return PyErr_NoMemory();
    }
    return (PyObject *)self;
}

/** Blend.__new__(spec, time=None): spec as dict, str or bytes-like JSON text. */
static PyObject *Blend_new(PyTypeObject *tp, PyObject *args, PyObject *kwds)
{
    static char *kwlist[] = {"spec", "time", NULL};
    PyObject *spec, *time_obj = Py_None;
    if (!PyArg_ParseTupleAndKeywords(args, kwds, "O|O:Blend", kwlist, &spec, &time_obj))
        return NULL;
    int has_time;
    double time = 0.0;
    if (parse_opt_number(time_obj, "Blend", "time", &has_time, &time) < 0)
        return NULL;

    PyObject *owner = NULL, *res = NULL;
    if (PyDict_Check(spec)) {
        /* Serialise with the json module; NaN and infinities reach the spec reader, which
         * rejects them naming the field. */
        PyObject *json = PyImport_ImportModule("json");
        PyObject *dumps = json ? PyObject_GetAttrString(json, "dumps") : NULL;
        Py_XDECREF(json);
        if (!dumps)
            return NULL;
        PyObject *a = PyTuple_Pack(1, spec), *kw = Py_BuildValue("{s:O}", "allow_nan", Py_True);
        if (a && kw)
            owner = PyObject_Call(dumps, a, kw);
        Py_XDECREF(a);
        Py_XDECREF(kw);
        Py_DECREF(dumps);
        if (!owner)
            return NULL;
        spec = owner;
    }
    if (PyUnicode_Check(spec)) {
        Py_ssize_t len;
        const char *text = PyUnicode_AsUTF8AndSize(spec, &len);
        if (text)
            res = blend_make(tp, text, len, NULL, has_time, time);
    } else if (PyObject_CheckBuffer(spec)) {
        /* Copy: the GIL is held throughout, but a bytearray must not change under us. */
        Py_buffer view;
        if (PyObject_GetBuffer(spec, &view, PyBUF_SIMPLE) == 0) {
            char *copy = PyMem_Malloc((size_t)view.len + 1);
            if (copy) {
                memcpy(copy, view.buf, (size_t)view.len);
                copy[view.len] = '\0';
            }
            Py_ssize_t len = view.len;
            PyBuffer_Release(&view);
            if (copy) {
                res = blend_make(tp, copy, len, NULL, has_time, time);
                PyMem_Free(copy);
            } else {
                PyErr_NoMemory();
            }
        }
    } else {
        PyErr_Format(PyExc_TypeError,
                     "Blend: spec must be a dict, a str or bytes of JSON text (got %s)",
                     tname(spec));
    }
    Py_XDECREF(owner);
    return res;
}

/** Blend.from_file(path, time=None): read a spec file (OSError when it cannot be read). */
static PyObject *Blend_from_file(PyObject *cls, PyObject *args, PyObject *kwds)
{
    static char *kwlist[] = {"path", "time", NULL};
    PyObject *path = NULL, *time_obj = Py_None;
    if (!PyArg_ParseTupleAndKeywords(args, kwds, "O&|O:from_file", kwlist, PyUnicode_FSConverter,
                                     &path, &time_obj))
        return NULL;
    int has_time;
    double time = 0.0;
    PyObject *res = NULL;
    const char *p = PyBytes_AS_STRING(path);
    if (parse_opt_number(time_obj, "from_file", "time", &has_time, &time) == 0) {
        if (strcmp(p, "-") == 0 || p[0] == '\0')
            PyErr_Format(PyExc_ValueError, "from_file: path must name a file (got '%s')", p);
        else
            res = blend_make((PyTypeObject *)cls, NULL, 0, p, has_time, time);
    }
    Py_DECREF(path);
    return res;
}

/** tp_dealloc: free the kernel objects (blend before its spec) and the lock. */
static void Blend_dealloc(BlendObject *self)
{
    PyTypeObject *tp = Py_TYPE(self);
    c2b_blend_destroy(self->blend);
    c2b_spec_destroy(self->spec);
    if (self->lock)
        PyThread_free_lock(self->lock);
    freefunc tp_free = (freefunc)PyType_GetSlot(tp, Py_tp_free);
    tp_free(self);
    Py_DECREF(tp);
}

/** Move the blend to time t if it is elsewhere. Caller holds the object lock and the GIL
 *  (set_time may reach FFTW's planner and libmatheval). */
static c2b_status blend_goto(BlendObject *self, double t, c2b_error *err)
{
    if (t == c2b_blend_time(self->blend))
        return C2B_OK;
    return c2b_blend_set_time(self->blend, t, err);
}

/** eval() and eval_grid(): argument conversion, evaluation without the GIL, result array. */
static PyObject *blend_evaluate(BlendObject *self, PyObject *args, PyObject *kwds, int grid)
{
    static char *kwlist[] = {"u", "v", "t", "derivs", NULL};
    const char *method = grid ? "eval_grid" : "eval";
    PyObject *uo, *vo, *to = Py_None;
    int derivs = 0;
    if (!PyArg_ParseTupleAndKeywords(args, kwds, grid ? "OO|Op:eval_grid" : "OO|Op:eval", kwlist,
                                     &uo, &vo, &to, &derivs))
        return NULL;
    c2blend_state *st = state_of_type(Py_TYPE(self));
    if (!st)
        return NULL;
    int has_t;
    double t = 0.0;
    if (parse_opt_number(to, method, "t", &has_t, &t) < 0)
        return NULL;
    dvec u, v;
    dvec_init(&u);
    dvec_init(&v);
    PyObject *res = NULL;
    if (dvec_from(uo, method, "u", &u) < 0 || dvec_from(vo, method, "v", &v) < 0)
        goto done;
    if (!grid && u.n != v.n) {
        /* A Python number is repeated to the other argument's length. */
        if (u.scalar && !v.scalar && v.n > 0) {
            if (dvec_broadcast(&u, v.n) < 0)
                goto done;
        } else if (v.scalar && !u.scalar && u.n > 0) {
            if (dvec_broadcast(&v, u.n) < 0)
                goto done;
        } else {
            PyErr_Format(PyExc_ValueError, "eval: u and v must have the same length (%zd vs %zd)",
                         u.n, v.n);
            goto done;
        }
    }
    int order = derivs ? C2B_MAX_DERIV : 0;
    size_t nd = c2b_blend_deriv_count(order);
    size_t npts = grid ? (size_t)u.n * (size_t)v.n : (size_t)u.n;
    /* The kernel's point limit, checked before the output is allocated. */
    long limit = c2b_spec_problem(self->spec)->tol.max_eval_points;
    if (grid && v.n && (size_t)u.n > SIZE_MAX / (size_t)v.n)
        npts = SIZE_MAX;
    if (npts > (size_t)limit) {
        raise_status(st, C2B_ERR_LIMIT, "%s: %zu points requested, the limit is %ld", method,
                     npts, limit);
        goto done;
    }
    double *out = NULL;
    PyObject *ba = new_doubles(npts * nd * 3, &out);
    if (!ba)
        goto done;
    c2b_error err;
    c2b_error_clear(&err);
    c2b_status s = C2B_OK;
    blend_lock(self);
    if (has_t)
        s = blend_goto(self, t, &err);
    if (!s && npts) {
        const c2b_blend *b = self->blend;
        Py_BEGIN_ALLOW_THREADS
        s = grid ? c2b_blend_eval_grid(b, (size_t)u.n, u.data, (size_t)v.n, v.data, order, out,
                                       &err)
                 : c2b_blend_eval(b, npts, u.data, v.data, order, out, &err);
        Py_END_ALLOW_THREADS
    }
    blend_unlock(self);
    if (s) {
        Py_DECREF(ba);
        raise_kernel(st, &err);
        goto done;
    }
    Py_ssize_t shape[4];
    int ndim = 0;
    shape[ndim++] = u.n;
    if (grid)
        shape[ndim++] = v.n;
    if (derivs)
        shape[ndim++] = (Py_ssize_t)nd;
    shape[ndim++] = 3;
    res = wrap_array(st, ba, ndim, shape);
done:
    dvec_free(&u);
    dvec_free(&v);
    return res;
}

PyDoc_STRVAR(Blend_eval_doc,
"eval(u, v, t=None, derivs=False) -> array\n"
"\n"
"Evaluate the blend at the points (u[i], v[i]).\n"
"\n"
"u and v are equal-length sequences of floats or buffers of doubles (numpy float64\n"
"arrays, any stride), or Python numbers (a number is repeated to the other argument's\n"
"length; two numbers give one point). u runs from 0 (first trimline) to 1 (second), v\n"
"over the spec's v_range. With t, the blend first moves to time t (and stays there).\n"
"\n"
"Returns shape (n, 3), or (n, 10, 3) with derivs=True in the order\n"
"[S, Su, Sv, Suu, Suv, Svv, Suuu, Suuv, Suvv, Svvv]: a numpy.ndarray when numpy is\n"
"installed, else a memoryview.");

/** eval(u, v, t=None, derivs=False): points, optionally with derivatives up to order 3. */
static PyObject *Blend_eval(BlendObject *self, PyObject *args, PyObject *kwds)
{
    return blend_evaluate(self, args, kwds, 0);
}

PyDoc_STRVAR(Blend_eval_grid_doc,
"eval_grid(u, v, t=None, derivs=False) -> array\n"
"\n"
"Evaluate the blend on the tensor grid u x v using its separable structure.\n"
"Returns shape (nu, nv, 3), or (nu, nv, 10, 3) with derivs=True; element [i, j] is\n"
"the point (u[i], v[j]). Arguments as for eval().");

/** eval_grid(u, v, t=None, derivs=False): separable grid evaluation. */
static PyObject *Blend_eval_grid(BlendObject *self, PyObject *args, PyObject *kwds)
{
    return blend_evaluate(self, args, kwds, 1);
}

PyDoc_STRVAR(Blend_set_time_doc,
"set_time(t)\n"
"\n"
"Move the blend to time t: time-dependent boundary data are re-projected. On failure\n"
"the blend keeps its previous time and surface.");

/** set_time(t): re-project the time-dependent data (atomic in the kernel). */
static PyObject *Blend_set_time(BlendObject *self, PyObject *arg)
{
    c2blend_state *st = state_of_type(Py_TYPE(self));
    if (!st)
        return NULL;
    int has;
    double t = 0.0;
    if (arg == Py_None) {
        PyErr_SetString(PyExc_TypeError, "set_time: t must be a number (got NoneType)");
        return NULL;
    }
    if (parse_opt_number(arg, "set_time", "t", &has, &t) < 0)
        return NULL;
    c2b_error err;
    c2b_error_clear(&err);
    blend_lock(self);
    c2b_status s = blend_goto(self, t, &err);
    blend_unlock(self);
    if (s)
        return raise_kernel(st, &err);
    Py_RETURN_NONE;
}

/** .time: the current time. */
static PyObject *Blend_get_time(BlendObject *self, void *closure)
{
    (void)closure;
    blend_lock(self);
    double t = c2b_blend_time(self->blend);
    blend_unlock(self);
    return PyFloat_FromDouble(t);
}

/** .domain: (v0, v1), the v range. */
static PyObject *Blend_get_domain(BlendObject *self, void *closure)
{
    (void)closure;
    c2b_vdomain d = c2b_blend_domain(self->blend);
    return Py_BuildValue("(dd)", d.v0, d.v1);
}

/** .periodic: closed trimlines. */
static PyObject *Blend_get_periodic(BlendObject *self, void *closure)
{
    (void)closure;
    return PyBool_FromLong(c2b_blend_domain(self->blend).periodic);
}

/** .continuity: "C1", "C2", "C3" or "ODE". */
static PyObject *Blend_get_continuity(BlendObject *self, void *closure)
{
    (void)closure;
    return PyUnicode_FromString(c2b_continuity_name(c2b_spec_problem(self->spec)->continuity));
}

/** .constraints: boundary rows per trimline (2 for C1, 3 for C2 and ODE, 4 for C3). */
static PyObject *Blend_get_constraints(BlendObject *self, void *closure)
{
    (void)closure;
    return PyLong_FromLong(c2b_blend_constraints(self->blend));
}

/** .name: the spec's "name" ("" when absent). */
static PyObject *Blend_get_name(BlendObject *self, void *closure)
{
    (void)closure;
    const char *name = c2b_spec_name(self->spec);
    return PyUnicode_DecodeUTF8(name, (Py_ssize_t)strlen(name), "replace");
}

/** .has_primaries: the spec defines primary surfaces (check() needs them). */
static PyObject *Blend_get_has_primaries(BlendObject *self, void *closure)
{
    (void)closure;
    return PyBool_FromLong(c2b_spec_has_primaries(self->spec));
}

/** repr(): name, continuity, v range, periodicity and time. */
static PyObject *Blend_repr(BlendObject *self)
{
    c2b_vdomain d = c2b_blend_domain(self->blend);
    blend_lock(self);
    double t = c2b_blend_time(self->blend);
    blend_unlock(self);
    char buf[160];
    PyOS_snprintf(buf, sizeof buf, " %s, v in [%.17g, %.17g]%s, t=%.17g>",
                  c2b_continuity_name(c2b_spec_problem(self->spec)->continuity), d.v0, d.v1,
                  d.periodic ? " periodic" : "", t);
    PyObject *name = Blend_get_name(self, NULL);
    if (!name)
        return NULL;
    PyObject *r = PyUnicode_FromFormat("<c2blend.Blend %R%s", name, buf);
    Py_DECREF(name);
    return r;
}

/** Parse JSON text with the json module (json.loads). */
static PyObject *json_loads(const char *text, size_t len)
{
    PyObject *json = PyImport_ImportModule("json");
    if (!json)
        return NULL;
    PyObject *s = PyUnicode_DecodeUTF8(text, (Py_ssize_t)len, "replace");
    PyObject *res = s ? PyObject_CallMethod(json, "loads", "O", s) : NULL;
    Py_XDECREF(s);
    Py_DECREF(json);
    return res;
}

/* Dictionary helpers: set key to a new reference (consumed); -1 on failure. */
static int dset(PyObject *d, const char *key, PyObject *val)
{
    if (!val)
        return -1;
    int rc = PyDict_SetItemString(d, key, val);
    Py_DECREF(val);
    return rc;
}

static int dset_f(PyObject *d, const char *key, double x)
{
    return dset(d, key, PyFloat_FromDouble(x));
}

static int dset_i(PyObject *d, const char *key, long x)
{
    return dset(d, key, PyLong_FromLong(x));
}

/** {"S": r[0], "S_u": r[1], ...} for the first n rows. */
static PyObject *rows_dict(const double *r, int n)
{
    PyObject *d = PyDict_New();
    for (int k = 0; d && k < n; k++)
        if (dset_f(d, c2b_row_names[k], r[k]) < 0)
            Py_CLEAR(d);
    return d;
}

/** {"u0": rows_dict(r0), "u1": rows_dict(r1)}. */
static PyObject *sides_dict(const double *r0, const double *r1, int n)
{
    PyObject *d = PyDict_New();
    if (d && (dset(d, "u0", rows_dict(r0, n)) < 0 || dset(d, "u1", rows_dict(r1, n)) < 0))
        Py_CLEAR(d);
    return d;
}

/**
 * Knots of one direction in OpenCASCADE's form: distinct values and multiplicities.
 * Open: the full vector (n + p + 1 values), sum of mults = n + p + 1.
 * Periodic: the kernel stores n distinct poles and the n + 2p + 1 knots of the unwrapped
 * spline, whose domain is [k[p], k[n + p]] (one period). OCCT lists the distinct knots of
 * one period, k[p] .. k[n + p], with the first and last multiplicity equal and
 * sum(mults) - mults[-1] = n; a knot's multiplicity is counted over the whole unwrapped
 * vector, so copies of the period's end knots outside the period are included. OCCT's
 * flat periodic knot sequence then puts the first knot at index p like the unwrapped
 * vector does, so pole j of the kernel is OCCT's pole j + 1 (checked against FreeCAD in
 * tests/python/test_module.py).
 * @return 0, or -1 with an exception (RuntimeError for an inconsistent knot vector).
 */
static int occt_knots(const c2b_nurbs_surface *s, int dir, PyObject **knots_out,
                      PyObject **mults_out)
{
    const double *k = c2b_nurbs_surface_knots(s, dir);
    int nk = c2b_nurbs_surface_nknots(s, dir), n = c2b_nurbs_surface_npoles(s, dir);
    int p = c2b_nurbs_surface_degree(s, dir), periodic = c2b_nurbs_surface_periodic(s, dir);
    int lo = periodic ? p : 0, hi = periodic ? n + p : nk - 1;
    *knots_out = *mults_out = NULL;
    if (nk != n + p + 1 + (periodic ? p : 0) || hi >= nk) {
        PyErr_Format(PyExc_RuntimeError, "fit: inconsistent knot vector in direction %d", dir);
        return -1;
    }
    double eps = 1e-13 * fabs(k[hi] - k[lo]);
    PyObject *knots = PyList_New(0), *mults = PyList_New(0);
    long sum = 0, first = 0, last = 0;
    if (!knots || !mults)
        goto fail;
    for (int i = lo; i <= hi;) {
        int j = i;
        while (j + 1 <= hi && fabs(k[j + 1] - k[i]) <= eps)
            j++;
        long m = j - i + 1;
        if (periodic && (i == lo || j == hi)) {
            m = 0;
            for (int q = 0; q < nk; q++)
                m += fabs(k[q] - k[i]) <= eps;
        }
        PyObject *kv = PyFloat_FromDouble(k[i]), *mv = PyLong_FromLong(m);
        int rc = (kv && mv) ? (PyList_Append(knots, kv) | PyList_Append(mults, mv)) : -1;
        Py_XDECREF(kv);
        Py_XDECREF(mv);
        if (rc)
            goto fail;
        if (i == lo)
            first = m;
        last = m;
        sum += m;
        i = j + 1;
    }
    if (periodic ? (first != last || sum - last != n) : sum != nk) {
        PyErr_Format(PyExc_RuntimeError,
                     "fit: knot multiplicities of direction %d do not match %d poles of degree %d",
                     dir, n, p);
        goto fail;
    }
    *knots_out = knots;
    *mults_out = mults;
    return 0;
fail:
    Py_XDECREF(knots);
    Py_XDECREF(mults);
    return -1;
}

/** The fit result dictionary (see Blend_fit_doc). */
static PyObject *fit_dict(c2blend_state *st, const c2b_nurbs_surface *s, const c2b_fit_report *rep,
                          int n)
{
    int nu = c2b_nurbs_surface_npoles(s, 0), nv = c2b_nurbs_surface_npoles(s, 1);
    PyObject *d = PyDict_New();
    if (!d)
        return NULL;
    double *pp = NULL;
    PyObject *ba = new_doubles((size_t)nu * (size_t)nv * 3, &pp);
    if (!ba)
        goto fail;
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            double w[4];
            c2b_nurbs_surface_pole(s, i, j, w);
            if (w[3] != 1.0) {
                Py_DECREF(ba);
                PyErr_SetString(PyExc_RuntimeError, "fit: the fitted surface is rational");
                goto fail;
            }
            memcpy(pp + ((size_t)i * (size_t)nv + (size_t)j) * 3, w, 3 * sizeof(double));
        }
    Py_ssize_t shape[3] = {nu, nv, 3};
    if (dset(d, "poles", wrap_array(st, ba, 3, shape)) < 0)
        goto fail;
    static const char *const kn[2] = {"uknots", "vknots"}, *const mn[2] = {"umults", "vmults"},
                             *const pn[2] = {"uperiodic", "vperiodic"},
                             *const dn[2] = {"udegree", "vdegree"};
    for (int dir = 0; dir < 2; dir++) {
        PyObject *knots, *mults;
        if (occt_knots(s, dir, &knots, &mults) < 0)
            goto fail;
        if (dset(d, kn[dir], knots) < 0 || dset(d, mn[dir], mults) < 0 ||
            dset(d, pn[dir], PyBool_FromLong(c2b_nurbs_surface_periodic(s, dir))) < 0 ||
            dset_i(d, dn[dir], c2b_nurbs_surface_degree(s, dir)) < 0)
            goto fail;
    }
    double dom[4];
    c2b_nurbs_surface_domain(s, dom);
    if (dset(d, "domain", Py_BuildValue("(dddd)", dom[0], dom[1], dom[2], dom[3])) < 0 ||
        dset_f(d, "deviation", rep->deviation) < 0 || dset_f(d, "tolerance", rep->tolerance) < 0 ||
        dset_f(d, "bbox_diagonal", rep->bbox_diagonal) < 0 ||
        dset(d, "residuals", sides_dict(rep->residual[0], rep->residual[1], n)) < 0 ||
        dset(d, "site_residuals",
             sides_dict(rep->site_residual[0], rep->site_residual[1], n)) < 0 ||
        dset(d, "tilt", Py_BuildValue("{s:d,s:d}", "u0", rep->tilt[0], "u1", rep->tilt[1])) < 0 ||
        dset_f(d, "seconds", rep->seconds) < 0 || dset_i(d, "iterations", rep->iterations) < 0 ||
        dset_i(d, "check_points", rep->check_points) < 0 ||
        dset(d, "npoles", Py_BuildValue("(ii)", rep->npoles[0], rep->npoles[1])) < 0)
        goto fail;
    /* The kernel's own JSON form (a spec's primaries[i].nurbs), printed exactly. */
    cJSON *j = c2b_nurbs_surface_to_json(s);
    size_t len = j ? c2b_nurbs_json_print(j, 0, NULL, 0) : 0;
    char *text = j ? PyMem_Malloc(len + 1) : NULL;
    if (!text) {
        cJSON_Delete(j);
        PyErr_NoMemory();
        goto fail;
    }
    c2b_nurbs_json_print(j, 0, text, len + 1);
    cJSON_Delete(j);
    PyObject *nj = json_loads(text, len);
    PyMem_Free(text);
    if (dset(d, "nurbs", nj) < 0)
        goto fail;
    return d;
fail:
    Py_DECREF(d);
    return NULL;
}

PyDoc_STRVAR(Blend_fit_doc,
"fit(tol=1e-6, degree_v=5, max_poles=400, max_iter=30) -> dict\n"
"\n"
"Fit a non-rational B-spline surface to the blend at its current time, with measured\n"
"deviation (README, \"B-spline output\"). tol is relative to the bounding-box diagonal.\n"
"Raises NumericalError (with .deviation and .tolerance) when the tolerance is not\n"
"reached within max_poles per direction.\n"
"\n"
"Keys, ready for FreeCAD's Part.BSplineSurface().buildFromPolesMultsKnots(\n"
"    d['poles'].tolist(), d['umults'], d['vmults'], d['uknots'], d['vknots'],\n"
"    d['uperiodic'], d['vperiodic'], d['udegree'], d['vdegree']):\n"
"  poles (nu, nv, 3) array; uknots, vknots (distinct knots) and umults, vmults\n"
"  (multiplicities) in OpenCASCADE's convention (a periodic direction lists one period\n"
"  with equal first and last multiplicities and nv distinct poles); uperiodic,\n"
"  vperiodic; udegree, vdegree; domain (u0, u1, v0, v1): u in [0, 1], v over the\n"
"  spec's v_range.\n"
"Report: deviation, tolerance, bbox_diagonal (model units); residuals and\n"
"site_residuals {'u0': {'S': .., 'S_u': .., 'S_uu': ..}, 'u1': {...}}, the measured\n"
"maxima of |d^k S_fit/du^k - d^k S/du^k| along each trimline (dense v, resp. the\n"
"interpolation sites); tilt {'u0': .., 'u1': ..}, the largest angle (rad) between the\n"
"fit's and the blend's normals along each trimline (dense v); seconds; iterations;\n"
"check_points; npoles (nu, nv); nurbs (the\n"
"kernel's JSON form, usable as a spec's primaries[i].nurbs).");

/** fit(tol=1e-6, degree_v=5, max_poles=400, max_iter=30): certified B-spline surface. */
static PyObject *Blend_fit(BlendObject *self, PyObject *args, PyObject *kwds)
{
    static char *kwlist[] = {"tol", "degree_v", "max_poles", "max_iter", NULL};
    c2b_fit_options fo = c2b_fit_options_default();
    if (!PyArg_ParseTupleAndKeywords(args, kwds, "|diii:fit", kwlist, &fo.tol_rel, &fo.degree_v,
                                     &fo.max_poles, &fo.max_iter))
        return NULL;
    c2blend_state *st = state_of_type(Py_TYPE(self));
    if (!st)
        return NULL;
    if (!(fo.tol_rel > 0 && fo.tol_rel < 1)) {
        char buf[32];
        PyOS_snprintf(buf, sizeof buf, "%.17g", fo.tol_rel);
        PyErr_Format(PyExc_ValueError, "fit: tol must be a number in (0, 1) (got %s)", buf);
        return NULL;
    }
    if (fo.degree_v != 3 && fo.degree_v != 5) {
        PyErr_Format(PyExc_ValueError, "fit: degree_v must be 3 or 5 (got %d)", fo.degree_v);
        return NULL;
    }
    if (fo.max_poles < 16 || fo.max_poles > C2B_NURBS_MAX_POLES) {
        PyErr_Format(PyExc_ValueError, "fit: max_poles must be in 16..%d (got %d)",
                     C2B_NURBS_MAX_POLES, fo.max_poles);
        return NULL;
    }
    if (fo.max_iter < 1) {
        PyErr_Format(PyExc_ValueError, "fit: max_iter must be >= 1 (got %d)", fo.max_iter);
        return NULL;
    }
    c2b_error err;
    c2b_error_clear(&err);
    c2b_nurbs_surface *s = NULL;
    c2b_fit_report rep;
    memset(&rep, 0, sizeof rep);
    c2b_status status;
    blend_lock(self);
    const c2b_blend *b = self->blend;
    int n = c2b_blend_constraints(b);
    Py_BEGIN_ALLOW_THREADS
    status = c2b_fit_blend(b, &fo, &s, &rep, &err);
    Py_END_ALLOW_THREADS
    blend_unlock(self);
    if (status) {
        raise_kernel(st, &err);
        if (status == C2B_ERR_NUMERIC) {
            /* Attach what the fit reached to the NumericalError. */
            PyObject *et, *ev, *tb;
            PyErr_Fetch(&et, &ev, &tb);
            PyErr_NormalizeException(&et, &ev, &tb);
            if (ev) {
                PyObject *a = PyFloat_FromDouble(rep.deviation);
                PyObject *t = PyFloat_FromDouble(rep.tolerance);
                if (!a || !t || PyObject_SetAttrString(ev, "deviation", a) < 0 ||
                    PyObject_SetAttrString(ev, "tolerance", t) < 0)
                    PyErr_Clear();
                Py_XDECREF(a);
                Py_XDECREF(t);
            }
            PyErr_Restore(et, ev, tb);
        }
        return NULL;
    }
    PyObject *d = fit_dict(st, s, &rep, n);
    c2b_nurbs_surface_destroy(s);
    return d;
}

/** One c2b_check_max as two keys: name -> max, at -> v. */
static int dset_max(PyObject *d, const char *name, const char *at, const c2b_check_max *m)
{
    return dset_f(d, name, m->max) < 0 || dset_f(d, at, m->at_v) < 0 ? -1 : 0;
}

/** Rank of a verdict string, for the overall (weaker) verdict. */
static int verdict_rank(const char *v, const char *const *order)
{
    for (int i = 0; i < 3; i++)
        if (strcmp(v, order[i]) == 0)
            return 3 - i;
    return 0;
}

/** The report of one trimline as a dictionary (keys as in `c2blend check`). */
static PyObject *check_side_dict(const c2b_check_side *s)
{
    PyObject *d = PyDict_New();
    if (!d)
        return NULL;
    if (dset_i(d, "side", s->side) < 0 || dset_i(d, "samples", s->samples) < 0 ||
        dset_i(d, "degenerate_points", s->degenerate) < 0 ||
        dset_max(d, "g0_max", "g0_at_v", &s->g0) < 0 ||
        dset_max(d, "g1_max_rad", "g1_at_v", &s->g1) < 0 ||
        dset_max(d, "g2_max", "g2_at_v", &s->g2) < 0 ||
        dset_max(d, "g2_max_rel", "g2_rel_at_v", &s->g2_rel) < 0 ||
        dset_max(d, "dk1_max", "dk1_at_v", &s->dk1) < 0 ||
        dset_max(d, "dk2_max", "dk2_at_v", &s->dk2) < 0 ||
        dset_max(d, "dK_max", "dK_at_v", &s->dK) < 0 ||
        dset_max(d, "dH_max", "dH_at_v", &s->dH) < 0 ||
        dset_max(d, "c1_max", "c1_at_v", &s->c1) < 0 ||
        dset_max(d, "c2_max", "c2_at_v", &s->c2) < 0 ||
        dset_f(d, "length_scale", s->scale_length) < 0 ||
        dset_f(d, "curvature_scale", s->scale_curvature) < 0 ||
        dset(d, "verdict", PyUnicode_FromString(s->verdict)) < 0 ||
        dset(d, "parametric_verdict", PyUnicode_FromString(s->parametric_verdict)) < 0 ||
        dset(d, "table", Py_BuildValue("{s:(dd),s:(dd)}", "blend", s->table_blend[0],
                                       s->table_blend[1], "primary", s->table_primary[0],
                                       s->table_primary[1])) < 0) {
        Py_DECREF(d);
        return NULL;
    }
    return d;
}

PyDoc_STRVAR(Blend_check_doc,
"check(samples=101, g0_rel=1e-9, g1_rad=1e-8, g2_rel=1e-6, c_rel=1e-9) -> dict\n"
"\n"
"Continuity report against the primaries at `samples` matched points per trimline\n"
"(README, \"Checking continuity\"); needs a spec with primaries (SpecError otherwise).\n"
"Keys: time; tolerances {g0_rel, g1_rad, g2_rel, c_rel}; u0 and u1, each with\n"
"g0_max (distance), g1_max_rad (normal angle), g2_max and g2_max_rel (cross normal\n"
"curvature difference), dk1_max, dk2_max, dK_max, dH_max, c1_max, c2_max (parametric\n"
"|dS_u|, |dS_uu|), each with the v where it occurs (g0_at_v, ...), verdict\n"
"('G2', 'G1', 'G0', 'none'), parametric_verdict ('C2', 'C1', 'C0', 'none'),\n"
"degenerate_points, length_scale, curvature_scale and table {'blend': (along, across),\n"
"'primary': (along, across)} (thesis Table 4 normal curvatures at v0); verdict and\n"
"parametric_verdict: the weaker of the two trimlines.");

/** check(samples=101, ...): c2b_check_run() as a dictionary. */
static PyObject *Blend_check(BlendObject *self, PyObject *args, PyObject *kwds)
{
    static char *kwlist[] = {"samples", "g0_rel", "g1_rad", "g2_rel", "c_rel", NULL};
    c2b_check_options o = c2b_check_options_default();
    if (!PyArg_ParseTupleAndKeywords(args, kwds, "|idddd:check", kwlist, &o.samples, &o.g0_rel,
                                     &o.g1_rad, &o.g2_rel, &o.c_rel))
        return NULL;
    c2blend_state *st = state_of_type(Py_TYPE(self));
    if (!st)
        return NULL;
    if (o.samples < 2 || o.samples > 10000000) {
        PyErr_Format(PyExc_ValueError, "check: samples must be in 2..10000000 (got %d)", o.samples);
        return NULL;
    }
    if (check_positive(o.g0_rel, "check", "g0_rel") < 0 ||
        check_positive(o.g1_rad, "check", "g1_rad") < 0 ||
        check_positive(o.g2_rel, "check", "g2_rel") < 0 ||
        check_positive(o.c_rel, "check", "c_rel") < 0)
        return NULL;
    if (!c2b_spec_has_primaries(self->spec))
        return raise_status(st, C2B_ERR_ARG,
                            "check needs primaries in the spec: this spec gives explicit "
                            "boundary data (boundary_residual() reports how well they are "
                            "reproduced)");
    c2b_error err;
    c2b_error_clear(&err);
    c2b_check_side r[2];
    /* With the GIL held: primaries' symbolic derivatives are made on first use. */
    blend_lock(self);
    c2b_status s = c2b_check_run(self->blend, self->spec, &o, r, &err);
    double t = c2b_blend_time(self->blend);
    blend_unlock(self);
    if (s)
        return raise_kernel(st, &err);
    static const char *const gorder[3] = {"G2", "G1", "G0"}, *const corder[3] = {"C2", "C1", "C0"};
    int g = verdict_rank(r[0].verdict, gorder) <= verdict_rank(r[1].verdict, gorder) ? 0 : 1;
    int c = verdict_rank(r[0].parametric_verdict, corder) <=
                    verdict_rank(r[1].parametric_verdict, corder)
                ? 0
                : 1;
    PyObject *d = PyDict_New();
    if (d && (dset_f(d, "time", t) < 0 ||
              dset(d, "tolerances",
                   Py_BuildValue("{s:d,s:d,s:d,s:d}", "g0_rel", o.g0_rel, "g1_rad", o.g1_rad,
                                 "g2_rel", o.g2_rel, "c_rel", o.c_rel)) < 0 ||
              dset(d, "u0", check_side_dict(&r[0])) < 0 ||
              dset(d, "u1", check_side_dict(&r[1])) < 0 ||
              dset(d, "verdict", PyUnicode_FromString(r[g].verdict)) < 0 ||
              dset(d, "parametric_verdict", PyUnicode_FromString(r[c].parametric_verdict)) < 0))
        Py_CLEAR(d);
    return d;
}

PyDoc_STRVAR(Blend_info_doc,
"info() -> dict\n"
"\n"
"The kernel's description of the blend: modes per component with kind, beta and\n"
"amplitudes, characteristic roots, condition estimates, truncation errors and the time\n"
"per stage (parsed from the kernel's JSON).");

/** info(): c2b_blend_info_json() parsed with json.loads. */
static PyObject *Blend_info(BlendObject *self, PyObject *unused)
{
    (void)unused;
    c2blend_state *st = state_of_type(Py_TYPE(self));
    if (!st)
        return NULL;
    c2b_error err;
    c2b_error_clear(&err);
    size_t need = 0;
    char *buf = NULL;
    c2b_status s;
    blend_lock(self);
    s = c2b_blend_info_json(self->blend, NULL, 0, &need, &err);
    if (s == C2B_ERR_LIMIT || s == C2B_OK) {
        c2b_error_clear(&err);
        buf = malloc(need + 1);
        s = buf ? c2b_blend_info_json(self->blend, buf, need + 1, &need, &err)
                : c2b_error_set(&err, C2B_ERR_NOMEM, "info: out of memory");
    }
    blend_unlock(self);
    PyObject *res = s ? raise_kernel(st, &err) : json_loads(buf, strlen(buf));
    free(buf);
    return res;
}

PyDoc_STRVAR(Blend_boundary_residual_doc,
"boundary_residual(samples=201) -> dict\n"
"\n"
"How well the blend reproduces its boundary data: at `samples` uniformly spaced v,\n"
"d^k S/du^k at u = 0 and 1 against the problem's boundary functions (sampled data at\n"
"their own sample points). Keys: residuals and scales, each {'u0': {'S': .., 'S_u': ..,\n"
"...}, 'u1': {...}} (maximum absolute difference, maximum magnitude of the datum);\n"
"samples; truncation_error (of the boundary data expansion, model units);\n"
"max_condition (largest condition estimate over the modes).");

/** boundary_residual(samples=201): c2b_blend_boundary_residual() as a dictionary. */
static PyObject *Blend_boundary_residual(BlendObject *self, PyObject *args, PyObject *kwds)
{
    static char *kwlist[] = {"samples", NULL};
    int ns = 201;
    if (!PyArg_ParseTupleAndKeywords(args, kwds, "|i:boundary_residual", kwlist, &ns))
        return NULL;
    c2blend_state *st = state_of_type(Py_TYPE(self));
    if (!st)
        return NULL;
    if (ns < 2 || ns > 10000000) {
        PyErr_Format(PyExc_ValueError, "boundary_residual: samples must be in 2..10000000 (got %d)",
                     ns);
        return NULL;
    }
    c2b_error err;
    c2b_error_clear(&err);
    double res[2 * C2B_MAX_N], scale[2 * C2B_MAX_N];
    /* With the GIL held: the boundary functions are libmatheval evaluators. */
    blend_lock(self);
    int n = c2b_blend_constraints(self->blend);
    c2b_status s = c2b_blend_boundary_residual(self->blend, ns, res, scale, &err);
    double trunc = c2b_blend_truncation_error(self->blend);
    double cond = c2b_blend_max_condition(self->blend);
    blend_unlock(self);
    if (s)
        return raise_kernel(st, &err);
    PyObject *d = PyDict_New();
    if (d && (dset_i(d, "samples", ns) < 0 ||
              dset(d, "residuals", sides_dict(res, res + n, n)) < 0 ||
              dset(d, "scales", sides_dict(scale, scale + n, n)) < 0 ||
              dset_f(d, "truncation_error", trunc) < 0 || dset_f(d, "max_condition", cond) < 0))
        Py_CLEAR(d);
    return d;
}

PyDoc_STRVAR(Blend_from_file_doc,
"Blend.from_file(path, time=None) -> Blend\n"
"\n"
"Read a spec file (OSError when it cannot be read; SpecError for a bad spec).");

static PyMethodDef Blend_methods[] = {
    {"eval", (PyCFunction)(void (*)(void))Blend_eval, METH_VARARGS | METH_KEYWORDS, Blend_eval_doc},
    {"eval_grid", (PyCFunction)(void (*)(void))Blend_eval_grid, METH_VARARGS | METH_KEYWORDS,
     Blend_eval_grid_doc},
    {"set_time", (PyCFunction)Blend_set_time, METH_O, Blend_set_time_doc},
    {"fit", (PyCFunction)(void (*)(void))Blend_fit, METH_VARARGS | METH_KEYWORDS, Blend_fit_doc},
    {"check", (PyCFunction)(void (*)(void))Blend_check, METH_VARARGS | METH_KEYWORDS,
     Blend_check_doc},
    {"info", (PyCFunction)Blend_info, METH_NOARGS, Blend_info_doc},
    {"boundary_residual", (PyCFunction)(void (*)(void))Blend_boundary_residual,
     METH_VARARGS | METH_KEYWORDS, Blend_boundary_residual_doc},
    {"from_file", (PyCFunction)(void (*)(void))Blend_from_file,
     METH_VARARGS | METH_KEYWORDS | METH_CLASS, Blend_from_file_doc},
    {NULL, NULL, 0, NULL}};

static PyGetSetDef Blend_getset[] = {
    {"time", (getter)Blend_get_time, NULL, "The current time t (float).", NULL},
    {"domain", (getter)Blend_get_domain, NULL, "The v range (v0, v1) of the trimlines.", NULL},
    {"periodic", (getter)Blend_get_periodic, NULL, "True for closed (periodic) trimlines.", NULL},
    {"continuity", (getter)Blend_get_continuity, NULL, "'C1', 'C2', 'C3' or 'ODE'.", NULL},
    {"constraints", (getter)Blend_get_constraints, NULL,
     "Boundary rows per trimline: 2 (C1), 3 (C2, ODE) or 4 (C3).", NULL},
    {"name", (getter)Blend_get_name, NULL, "The spec's name ('' when absent).", NULL},
    {"has_primaries", (getter)Blend_get_has_primaries, NULL,
     "True when the spec defines primary surfaces (needed by check()).", NULL},
    {NULL, NULL, NULL, NULL, NULL}};

PyDoc_STRVAR(Blend_doc,
"Blend(spec, time=None)\n"
"\n"
"A PDE blend surface S(u, v, t) between two trimlines, built by the C2Blend kernel.\n"
"\n"
"spec is a dict (serialised with json.dumps(spec, allow_nan=True)) or JSON text as str\n"
"or bytes, in the format of README.md \"Spec format\". The blend is built at `time`, or\n"
"at the spec's \"time\". It is the exact closed form: a spec with an approximate\n"
"\"solver\" (docs/APPROX.md) raises SpecError; the CLI's `c2blend eval` evaluates those.\n"
"Errors: SpecError naming the field, NumericalError for a resonant mode. A Blend may be\n"
"shared between threads: its methods are serialised.");

static PyType_Slot Blend_slots[] = {
    {Py_tp_doc, (void *)Blend_doc},
    {Py_tp_new, (void *)Blend_new},
    {Py_tp_dealloc, (void *)Blend_dealloc},
    {Py_tp_repr, (void *)Blend_repr},
    {Py_tp_methods, Blend_methods},
    {Py_tp_getset, Blend_getset},
    {0, NULL}};

static PyType_Spec Blend_spec = {
    .name = "c2blend.Blend",
    .basicsize = sizeof(BlendObject),
    .itemsize = 0,
    .flags = Py_TPFLAGS_DEFAULT | Py_TPFLAGS_IMMUTABLETYPE,
    .slots = Blend_slots,
};

/* ---- the module ------------------------------------------------------------------------ */

/** Create the exception hierarchy, the Blend type and the constants (Py_mod_exec). */
static int c2blend_exec(PyObject *m)
{
    c2blend_state *st = state_of_module(m);
    st->Error = PyErr_NewExceptionWithDoc(
        "c2blend.Error",
        "Base class of the kernel's errors; .status is the kernel's status code.",
        PyExc_Exception, NULL);
    if (!st->Error || PyModule_AddObjectRef(m, "Error", st->Error) < 0)
        return -1;
    st->SpecError = PyErr_NewExceptionWithDoc(
        "c2blend.SpecError",
        "Invalid spec, argument or size (kernel status ERR_SPEC, ERR_ARG, ERR_LIMIT); the "
        "message names the field.",
        st->Error, NULL);
    if (!st->SpecError || PyModule_AddObjectRef(m, "SpecError", st->SpecError) < 0)
        return -1;
    st->NumericalError = PyErr_NewExceptionWithDoc(
        "c2blend.NumericalError",
        "Resonant or ill-conditioned mode, or a fit that did not reach its tolerance (kernel "
        "status ERR_NUMERIC).",
        st->Error, NULL);
    if (!st->NumericalError || PyModule_AddObjectRef(m, "NumericalError", st->NumericalError) < 0)
        return -1;
    st->BlendType = PyType_FromModuleAndSpec(m, &Blend_spec, NULL);
    if (!st->BlendType || PyModule_AddObjectRef(m, "Blend", st->BlendType) < 0)
        return -1;
    if (PyModule_AddIntConstant(m, "ERR_ARG", C2B_ERR_ARG) < 0 ||
        PyModule_AddIntConstant(m, "ERR_SPEC", C2B_ERR_SPEC) < 0 ||
        PyModule_AddIntConstant(m, "ERR_NUMERIC", C2B_ERR_NUMERIC) < 0 ||
        PyModule_AddIntConstant(m, "ERR_NOMEM", C2B_ERR_NOMEM) < 0 ||
        PyModule_AddIntConstant(m, "ERR_IO", C2B_ERR_IO) < 0 ||
        PyModule_AddIntConstant(m, "ERR_LIMIT", C2B_ERR_LIMIT) < 0 ||
        PyModule_AddStringConstant(m, "__version__", C2B_VERSION) < 0)
        return -1;
    return 0;
}

/** m_traverse: the objects held by the module state. */
static int c2blend_traverse(PyObject *m, visitproc visit, void *arg)
{
    c2blend_state *st = state_of_module(m);
    Py_VISIT(st->Error);
    Py_VISIT(st->SpecError);
    Py_VISIT(st->NumericalError);
    Py_VISIT(st->BlendType);
    Py_VISIT(st->frombuffer);
    return 0;
}

/** m_clear: drop the objects held by the module state. */
static int c2blend_clear(PyObject *m)
{
    c2blend_state *st = state_of_module(m);
    Py_CLEAR(st->Error);
    Py_CLEAR(st->SpecError);
    Py_CLEAR(st->NumericalError);
    Py_CLEAR(st->BlendType);
    Py_CLEAR(st->frombuffer);
    return 0;
}

/** m_free: as m_clear, when the module is deallocated. */
static void c2blend_free(void *m)
{
    c2blend_clear((PyObject *)m);
}

static PyModuleDef_Slot c2blend_slots[] = {
    {Py_mod_exec, (void *)c2blend_exec},
    {0, NULL}};

PyDoc_STRVAR(c2blend_doc,
"C2Blend: curvature-continuous PDE blend surfaces (C1, C2, C3 and ODE blends).\n"
"\n"
"    import c2blend\n"
"    b = c2blend.Blend(spec_dict_or_json)     # README.md, \"Spec format\"\n"
"    xyz = b.eval(u, v)                        # (n, 3)\n"
"    d = b.eval(u, v, derivs=True)             # (n, 10, 3): S, Su, Sv, Suu, ...\n"
"    g = b.eval_grid(us, vs)                   # (nu, nv, 3)\n"
"    f = b.fit(tol=1e-6)                       # B-spline surface, OCCT knot form\n"
"    r = b.check()                             # G0/G1/G2 and C1/C2 at the trimlines\n"
"\n"
"Errors: Error, with SpecError (bad spec, argument or size) and NumericalError\n"
"(resonant mode, fit tolerance not reached); each has .status, the kernel's code\n"
"(ERR_SPEC, ERR_ARG, ...). Out of memory raises MemoryError, unreadable files OSError.");

static struct PyModuleDef c2blend_module = {
    PyModuleDef_HEAD_INIT,
    .m_name = "c2blend",
    .m_doc = c2blend_doc,
    .m_size = sizeof(c2blend_state),
    .m_slots = c2blend_slots,
    .m_traverse = c2blend_traverse,
    .m_clear = c2blend_clear,
    .m_free = c2blend_free,
};

/** Module entry point: multi-phase initialisation (PEP 489). */
PyMODINIT_FUNC PyInit_c2blend(void)
{
    return PyModuleDef_Init(&c2blend_module);
}
