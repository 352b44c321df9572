/**
 * @file c2b_nurbs_json.h
 * NURBS curves and surfaces as JSON objects (cJSON).
 *
 * Surface: {"degree": [p, q], "knots_u": [...], "knots_v": [...],
 *           "poles": [[[x, y, z, w], ...], ...], "periodic": [false, false]}
 *   poles has n_u rows of n_v entries [x, y, z, w] (all four numbers required; distinct
 *   poles only when periodic); the knot vectors are full (n + p + 1 values, or n + 2p + 1
 *   when periodic, see c2b_nurbs.h); "periodic" is optional (default both false).
 * Curve:   {"degree": p, "knots": [...], "poles": [[x, y, z, w], ...], "periodic": false}
 *
 * Unknown and duplicate keys are rejected. Every message starts with the field path
 * given by the caller ("primaries[0].nurbs.knots_u: decreasing at index 5 (0.4 after 0.5)").
 *
 * The writers produce the same format; a round trip through them in memory gives back
 * the object bit for bit (negative zeros are stored as +0 when created). As text, use
 * c2b_nurbs_json_print(): cJSON_Print() is NOT exact, since cJSON 1.7 keeps its 15-digit
 * form whenever that reads back within a relative DBL_EPSILON, so about one double in
 * eight comes back one unit in the last place off.
 */
#ifndef C2B_NURBS_JSON_H
#define C2B_NURBS_JSON_H

#include <cjson/cJSON.h>

#include "c2b_nurbs.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * Read a surface from a JSON object.
 * @param obj    the object (NULL is reported as missing)
 * @param field  path prefix of every message, e.g. "primaries[0].nurbs" (NULL or "" for none)
 * @param out    receives the new surface (NULL on failure); free with c2b_nurbs_surface_destroy()
 * @return C2B_OK; C2B_ERR_SPEC for a malformed or invalid object (message names the field);
 *         C2B_ERR_LIMIT for more than C2B_NURBS_MAX_POLES poles in a direction;
 *         C2B_ERR_ARG when out is NULL; C2B_ERR_NOMEM.
 */
c2b_status c2b_nurbs_surface_from_json(const cJSON *obj, const char *field,
                                       c2b_nurbs_surface **out, c2b_error *err);

/** The surface as a new JSON object in the format above (free with cJSON_Delete());
 *  NULL when s is NULL or on allocation failure. */
cJSON *c2b_nurbs_surface_to_json(const c2b_nurbs_surface *s);

/** Read a curve; as c2b_nurbs_surface_from_json(). */
c2b_status c2b_nurbs_curve_from_json(const cJSON *obj, const char *field, c2b_nurbs_curve **out,
                                     c2b_error *err);

/** The curve as a new JSON object (free with cJSON_Delete()); NULL on failure. */
cJSON *c2b_nurbs_curve_to_json(const c2b_nurbs_curve *c);

/**
 * Print any cJSON tree as JSON text in which every number reads back exactly (the
 * shortest of 15, 16 or 17 significant digits that does). snprintf-style: writes at most
 * len bytes including the terminating NUL into buf (buf may be NULL when len is 0) and
 * returns the length of the full text, so a first call with len 0 gives the size.
 * formatted: 0 for compact text; 1 for one key per line, with arrays of scalars kept on
 * one line. Non-finite numbers print as null (as cJSON does).
 */
size_t c2b_nurbs_json_print(const cJSON *item, int formatted, char *buf, size_t len);

#ifdef __cplusplus
}
#endif
#endif
