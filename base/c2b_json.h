/**
 * @file c2b_json.h
 * The key check shared by every C2Blend JSON reader (blend specs, NURBS files).
 */
#ifndef C2B_JSON_H
#define C2B_JSON_H

#include <cjson/cJSON.h>

#include "c2b_error.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * Check the keys of the JSON object obj, called `self` in messages ("" for a spec's top
 * level, whose messages then carry no prefix).
 *
 * keys is a NULL-terminated list of the allowed keys, or NULL to allow any key (an object
 * of names, such as a spec's constants; the time then grows as the square of the number
 * of keys, which the caller bounds first). With items non-NULL, items[i] receives the value
 * of keys[i], or NULL where it is absent; items must hold as many pointers as keys has
 * entries. The values stay owned by obj.
 *
 * Errors, all C2B_ERR_SPEC and naming self and the key: obj NULL ("missing"); obj not an
 * object ("expected an object", followed by `form` when it is not NULL, to show the
 * expected form); a key outside keys (the message lists the allowed ones); a key given
 * twice, which JSON parsers would otherwise resolve silently to one of the two values; one
 * of the first `required` keys absent.
 */
c2b_status c2b_json_keys(const cJSON *obj, const char *self, const char *form,
                         const char *const *keys, int required, const cJSON **items,
                         c2b_error *err);

#ifdef __cplusplus
}
#endif

#endif
