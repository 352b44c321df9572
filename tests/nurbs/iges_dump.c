/*
 * iges_dump: test driver for c2b_iges_write_surface().
 *
 *   iges_dump SURFACE.json OUT.igs [--units NAME] [--grid N]
 *   iges_dump --check-args SURFACE.json
 *
 * SURFACE.json holds one surface in the spec form
 *   {"degree": [p, q], "knots_u": [...], "knots_v": [...],
 *    "poles": [[[x, y, z, w], ...], ...], "periodic": [false, false]}
 * (or an object with that surface under "surface"). The surface is written to OUT.igs.
 * With --grid N the driver also prints, on stdout, the C2Blend evaluation of the surface
 * on an N x N grid spanning the domain (u outer, v inner) as JSON:
 *   {"domain": [u0, u1, v0, v1], "points": [[x, y, z], ...]}
 * --check-args calls the writer with a NULL surface, a NULL path and an empty path and
 * prints one line "<case>: <status name>: <message>" for each (exit 0 if every call
 * returned C2B_ERR_ARG).
 * Exit status: 0 on success, 1 on a library error (message on stderr), 2 on bad usage.
 */
#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "c2b_iges.h"
#include "c2b_nurbs.h"
#include "c2b_nurbs_json.h"

static char *read_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL)
        return NULL;
    size_t cap = 1 << 16, len = 0;
    char *buf = malloc(cap);
    while (buf != NULL) {
        len += fread(buf + len, 1, cap - len - 1, f);
        if (len < cap - 1)
            break;
        char *nb = realloc(buf, cap * 2);
        if (nb == NULL) {
            free(buf);
            buf = NULL;
            break;
        }
        buf = nb;
        cap *= 2;
    }
    int bad = ferror(f);
    fclose(f);
    if (buf == NULL || bad) {
        free(buf);
        return NULL;
    }
    buf[len] = '\0';
    return buf;
}

static int usage(void)
{
    fprintf(stderr, "usage: iges_dump SURFACE.json OUT.igs [--units NAME] [--grid N]\n"
                    "       iges_dump --check-args SURFACE.json\n");
    return 2;
}

static c2b_nurbs_surface *load(const char *path)
{
    char *text = read_file(path);
    if (text == NULL) {
        fprintf(stderr, "iges_dump: cannot read %s\n", path);
        return NULL;
    }
    cJSON *root = cJSON_Parse(text);
    free(text);
    if (root == NULL) {
        fprintf(stderr, "iges_dump: %s: malformed JSON\n", path);
        return NULL;
    }
    const cJSON *obj = cJSON_GetObjectItemCaseSensitive(root, "surface");
    if (obj == NULL)
        obj = root;
    c2b_error err;
    c2b_error_clear(&err);
    c2b_nurbs_surface *s = NULL;
    c2b_status st = c2b_nurbs_surface_from_json(obj, "surface", &s, &err);
    cJSON_Delete(root);
    if (st != C2B_OK) {
        fprintf(stderr, "iges_dump: %s: %s\n", c2b_status_name(st), err.msg);
        return NULL;
    }
    return s;
}

/* The argument errors of c2b_iges_write_surface(). */
static int check_args(const char *json)
{
    c2b_nurbs_surface *s = load(json);
    if (s == NULL)
        return 1;
    struct {
        const char *name;
        const c2b_nurbs_surface *s;
        const char *path;
    } cases[] = {{"null surface", NULL, "x.igs"}, {"null path", s, NULL}, {"empty path", s, ""}};
    int bad = 0;
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        c2b_error err;
        c2b_error_clear(&err);
        c2b_status st = c2b_iges_write_surface(cases[k].s, cases[k].path, NULL, &err);
        printf("%s: %s: %s\n", cases[k].name, c2b_status_name(st), err.msg);
        bad |= st != C2B_ERR_ARG || err.code != C2B_ERR_ARG;
        /* a NULL error record is allowed */
        bad |= c2b_iges_write_surface(cases[k].s, cases[k].path, NULL, NULL) != C2B_ERR_ARG;
    }
    c2b_nurbs_surface_destroy(s);
    return bad;
}

int main(int argc, char **argv)
{
    if (argc == 3 && strcmp(argv[1], "--check-args") == 0)
        return check_args(argv[2]);
    if (argc < 3)
        return usage();
    const char *units = NULL;
    int grid = 0;
    for (int a = 3; a < argc; a++) {
        if (strcmp(argv[a], "--units") == 0 && a + 1 < argc) {
            units = argv[++a];
        } else if (strcmp(argv[a], "--grid") == 0 && a + 1 < argc) {
            char *end;
            long g = strtol(argv[++a], &end, 10);
            if (*end != '\0' || g < 2 || g > 1000)
                return usage();
            grid = (int)g;
        } else {
            return usage();
        }
    }

    c2b_nurbs_surface *s = load(argv[1]);
    if (s == NULL)
        return 1;
    c2b_error err;
    c2b_error_clear(&err);
    c2b_status st = c2b_iges_write_surface(s, argv[2], units, &err);
    if (st != C2B_OK) {
        fprintf(stderr, "iges_dump: %s: %s\n", c2b_status_name(st), err.msg);
        c2b_nurbs_surface_destroy(s);
        return 1;
    }

    if (grid > 0) {
        double dom[4];
        c2b_nurbs_surface_domain(s, dom);
        printf("{\"domain\": [%.17g, %.17g, %.17g, %.17g], \"points\": [", dom[0], dom[1],
               dom[2], dom[3]);
        for (int i = 0; i < grid; i++)
            for (int j = 0; j < grid; j++) {
                double u = dom[0] + (dom[1] - dom[0]) * i / (grid - 1);
                double v = dom[2] + (dom[3] - dom[2]) * j / (grid - 1);
                double p[3];
                st = c2b_nurbs_surface_eval(s, u, v, 0, p, &err);
                if (st != C2B_OK) {
                    fprintf(stderr, "iges_dump: eval(%.17g, %.17g): %s\n", u, v, err.msg);
                    c2b_nurbs_surface_destroy(s);
                    return 1;
                }
                printf("%s[%.17g, %.17g, %.17g]", (i || j) ? ", " : "", p[0], p[1], p[2]);
            }
        printf("]}\n");
    }
    c2b_nurbs_surface_destroy(s);
    return 0;
}
