#include "c2b_json.h"

#include <stdio.h>
#include <string.h>

/* Whether `key` is in the NULL-terminated list (a NULL list allows every key). */
static int json_allowed(const char *const *keys, const char *key)
{
    if (!keys)
        return 1;
    for (int i = 0; keys[i]; i++)
        if (strcmp(key, keys[i]) == 0)
            return 1;
    return 0;
}

c2b_status c2b_json_keys(const cJSON *obj, const char *self, const char *form,
                         const char *const *keys, int required, const cJSON **items,
                         c2b_error *err)
{
    const char *sep = *self ? ": " : "";
    if (!obj)
        return c2b_error_set(err, C2B_ERR_SPEC, "%s%smissing", self, sep);
    if (!cJSON_IsObject(obj))
        return c2b_error_set(err, C2B_ERR_SPEC, "%s%sexpected an object%s%s", self, sep,
                             form ? " " : "", form ? form : "");
    for (const cJSON *x = obj->child; x; x = x->next) {
        const char *k = x->string ? x->string : "";
        if (!json_allowed(keys, k)) {
            char list[512] = "";
            size_t used = 0;
            for (int i = 0; keys[i] && used < sizeof list; i++)
                used += (size_t)snprintf(list + used, sizeof list - used, "%s%s", i ? ", " : "",
                                         keys[i]);
            return c2b_error_set(err, C2B_ERR_SPEC, "%s%sunknown key '%s' (allowed: %s)", self,
                                 sep, k, list);
        }
        for (const cJSON *y = obj->child; y != x; y = y->next)
            if (y->string && strcmp(y->string, k) == 0)
                return c2b_error_set(err, C2B_ERR_SPEC,
                                     "%s%sduplicate key '%s' (give each key once)", self, sep, k);
    }
    for (int i = 0; keys && keys[i]; i++) {
        const cJSON *v = cJSON_GetObjectItemCaseSensitive(obj, keys[i]);
        if (items)
            items[i] = v;
        if (!v && i < required)
            return c2b_error_set(err, C2B_ERR_SPEC, "%s%smissing key '%s'", self, sep, keys[i]);
    }
    return C2B_OK;
}
