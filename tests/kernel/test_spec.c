/*
 * Spec reader: every bad input is rejected with the expected status and a message
 * naming the field; good specs parse. Blend-level failures (resonance, non-finite
 * data) are checked through c2b_blend_create with the same messages.
 */
#include <string.h>

#include "c2b_blend.h"
#include "c2b_spec.h"
#include "test_util.h"

#define PRIM(x0, x1) \
    "\"primaries\": [{\"surface\": [" x0 "], \"trim_u\": 0.2, \"direction\": -1}," \
    " {\"surface\": [" x1 "], \"trim_u\": 0.3}]"
#define GOOD_PRIM PRIM("\"sin(2*pi*v)\", \"cos(2*pi*v)\", \"2+3*u^2\"", "\"0.8*sin(2*pi*v)\", \"0.8*cos(2*pi*v)\", \"-5*u^3\"")

typedef struct bad_case {
    const char *json;
    c2b_status spec_status;  /* expected from c2b_spec_parse */
    c2b_status blend_status; /* expected from c2b_blend_create when the spec parses */
    const char *fragment;
} bad_case;

static const bad_case CASES[] = {
    {"{\"periodic\": true, " GOOD_PRIM, C2B_ERR_SPEC, 0, "malformed JSON near line 1"},
    {"[1, 2]", C2B_ERR_SPEC, 0, "top level must be a JSON object"},
    {"{\"periodic\": true, \"colour\": 3, " GOOD_PRIM "}", C2B_ERR_SPEC, 0, "unknown key 'colour'"},
    {"{\"periodic\": true}", C2B_ERR_SPEC, 0, "missing 'primaries'"},
    /* a repeated key would otherwise silently take the first value (cJSON's lookup) */
    {"{\"continuity\": \"C1\", \"continuity\": \"C2\", " GOOD_PRIM "}", C2B_ERR_SPEC, 0,
     "duplicate key 'continuity' (give each key once)"},
    {"{\"constants\": {\"a\": 1, \"b\": 2, \"a\": 3}, " GOOD_PRIM "}", C2B_ERR_SPEC, 0,
     "constants: duplicate key 'a'"},
    {"{\"constants\": [1, 2], " GOOD_PRIM "}", C2B_ERR_SPEC, 0,
     "constants: expected an object of numbers"},
    {"{\"primaries\": [{\"surface\": [\"v\", \"u\", \"0\"], \"trim_u\": 0, \"trim_u\": 1},"
     " {\"surface\": [\"v\", \"u\", \"1\"], \"trim_u\": 0}]}",
     C2B_ERR_SPEC, 0, "primaries[0]: duplicate key 'trim_u'"},
    {"{\"shape\": {\"x\": [1,1,1,1], \"y\": [1,1,1,1], \"z\": [1,1,1,1], \"x\": [2,2,2,2]}, "
     GOOD_PRIM "}", C2B_ERR_SPEC, 0, "shape: duplicate key 'x'"},
    {"{\"continuity\": \"C4\", " GOOD_PRIM "}", C2B_ERR_SPEC, 0, "continuity: 'C4' is not one of"},
    {"{\"shape\": [1, 1, 1], " GOOD_PRIM "}", C2B_ERR_SPEC, 0, "shape: expected an array of 4 numbers"},
    {"{\"shape\": {\"x\": [1,1,1,1], \"y\": [1,1,1,1]}, " GOOD_PRIM "}", C2B_ERR_SPEC, 0, "shape.z: missing"},
    {"{\"shape\": [0, 1, 1, 1], " GOOD_PRIM "}", 0, C2B_ERR_SPEC, "gamma must be nonzero"},
    {"{\"v_range\": [1, 1], " GOOD_PRIM "}", C2B_ERR_SPEC, 0, "v_range: [1, 1] has zero or negative length"},
    {"{\"v_range\": [0, \"one\"], " GOOD_PRIM "}", C2B_ERR_SPEC, 0, "v_range[1]: expected a number"},
    {"{\"periodic\": 1, " GOOD_PRIM "}", C2B_ERR_SPEC, 0, "periodic: expected true or false"},
    {"{\"constants\": {\"h1\": \"2\"}, " GOOD_PRIM "}", C2B_ERR_SPEC, 0, "constants.h1: expected a number"},
    {"{\"constants\": {\"pi\": 3}, " GOOD_PRIM "}", C2B_ERR_SPEC, 0, "constants.pi: 'pi' is reserved"},
    {"{\"periodic\": true, " PRIM("\"sin(2*pi*v)\", \"cos(2*pi*v)\", \"2+3*u^2\"",
                                   "\"sin(2*pi*v)\", \"cos(2*pi*v)\", \"h4*u\"") "}",
     C2B_ERR_SPEC, 0, "primaries[1].surface[2]: unknown identifier 'h4'"},
    {"{\"periodic\": true, " PRIM("\"sinn(2*pi*v)\", \"cos(2*pi*v)\", \"1\"", "\"0\", \"0\", \"0\"") "}",
     C2B_ERR_SPEC, 0, "primaries[0].surface[0]: unknown function 'sinn'"},
    {"{\"periodic\": true, " PRIM("\"sin(2*pi*v\", \"cos(2*pi*v)\", \"1\"", "\"0\", \"0\", \"0\"") "}",
     C2B_ERR_SPEC, 0, "primaries[0].surface[0]: unbalanced '('"},
    {"{\"periodic\": true, " PRIM("\"sin(2*pi*v)\", \"cos(2*pi*v)\"", "\"0\", \"0\", \"0\"") "}",
     C2B_ERR_SPEC, 0, "primaries[0].surface: expected 3 expressions"},
    {"{\"periodic\": true, \"primaries\": [{\"surface\": [\"v\", \"0\", \"u\"], \"trim_u\": 0.2, \"direction\": 2},"
     " {\"surface\": [\"v\", \"1\", \"u\"], \"trim_u\": 0.3}]}",
     C2B_ERR_SPEC, 0, "primaries[0].direction: must be 1 or -1"},
    {"{\"primaries\": [{\"surface\": [\"v\", \"0\", \"u\"]}, {\"surface\": [\"v\", \"1\", \"u\"], \"trim_u\": 0.3}]}",
     C2B_ERR_SPEC, 0, "primaries[0].trim_u: missing"},
    {"{\"boundary\": {\"u0\": [[\"v\", \"0\", \"0\"], [\"0\", \"0\", \"0\"]], \"u1\": [[\"v\", \"1\", \"0\"], [\"0\", \"0\", \"0\"], [\"0\", \"0\", \"0\"]]}}",
     C2B_ERR_SPEC, 0, "boundary.u0: C2 needs 3 rows (S, S_u, S_uu), got 2"},
    {"{\"boundary\": {\"u0\": [[\"u*v\", \"0\", \"0\"], [\"0\", \"0\", \"0\"], [\"0\", \"0\", \"0\"]], \"u1\": [[\"v\", \"1\", \"0\"], [\"0\", \"0\", \"0\"], [\"0\", \"0\", \"0\"]]}}",
     C2B_ERR_SPEC, 0, "boundary.u0[0][0]: variable 'u' is not allowed here"},
    {"{\"boundary\": {\"u0\": [{\"samples\": [[0,0,0],[1,1,1]]}, [\"0\", \"0\", \"0\"], [\"0\", \"0\", \"0\"]], \"u1\": [[\"v\", \"1\", \"0\"], [\"0\", \"0\", \"0\"], [\"0\", \"0\", \"0\"]]}}",
     C2B_ERR_SPEC, 0, "boundary.u0[0].samples: 2 samples given, at least 7"},
    {"{\"boundary\": {\"u0\": [{\"samples\": [[0,0,0],[1,1,1],[2,2,2],[3,3],[4,4,4],[5,5,5],[6,6,6]]}, [\"0\", \"0\", \"0\"], [\"0\", \"0\", \"0\"]], \"u1\": [[\"v\", \"1\", \"0\"], [\"0\", \"0\", \"0\"], [\"0\", \"0\", \"0\"]]}}",
     C2B_ERR_SPEC, 0, "boundary.u0[0].samples[3]: expected an array of 3 numbers"},
    {"{\"periodic\": true, " PRIM("\"1/0\", \"cos(2*pi*v)\", \"1\"", "\"0\", \"0\", \"0\"") "}",
     0, C2B_ERR_SPEC, "primaries[0].surface[0] (d^0/du^0 at u=0.2): value is not finite (inf)"},
    {"{\"periodic\": true, " PRIM("\"sqrt(v-0.5)\", \"cos(2*pi*v)\", \"1\"", "\"0\", \"0\", \"0\"") "}",
     0, C2B_ERR_SPEC, "primaries[0].surface[0] (d^0/du^0 at u=0.2): value is not finite"},
    {"{\"periodic\": true, " PRIM("\"log(u-0.5)\", \"0\", \"0\"", "\"0\", \"0\", \"0\"") "}",
     0, C2B_ERR_SPEC, "primaries[0].surface[0] (d^0/du^0 at u=0.2): value is not finite"},
    /* C1 with c = 0 and d = -l^4/(16 pi^4), l = 4.730040744862704: clamped-beam resonance of
     * the cos(2 pi v) mode (see test_mode.c). */
    {"{\"continuity\": \"C1\", \"shape\": [1, 0, -0.32117375828767714], \"periodic\": true, "
     "\"boundary\": {\"u0\": [[\"cos(2*pi*v)\", \"0\", \"0\"], [\"0\", \"0\", \"0\"]], \"u1\": [[\"0\", \"0\", \"0\"], [\"0\", \"0\", \"0\"]]}}",
     0, C2B_ERR_NUMERIC, "component x, mode cos(omega=6.28"},
    /* NURBS primaries: each bad input names the field. */
#define NURBS_PRIM(body, trim) \
    "{\"primaries\": [{\"nurbs\": {" body "}, " trim "}," \
    " {\"nurbs\": {\"degree\": [1, 1], \"knots_u\": [0, 0, 1, 1], \"knots_v\": [0, 0, 1, 1]," \
    " \"poles\": [[[0,0,0,1],[1,0,0,1]],[[0,1,1,1],[1,1,1,1]]]}, \"trim_u\": 0}]}"
#define GOOD_POLES "\"poles\": [[[0,0,0,1],[1,0,0,1]],[[0,1,1,1],[1,1,1,1]]]"
    {NURBS_PRIM("\"degree\": [1, 1], \"knots_u\": [0, 0, 1, 0.5], \"knots_v\": [0, 0, 1, 1], " GOOD_POLES, "\"trim_u\": 1"),
     C2B_ERR_SPEC, 0, "primaries[0].nurbs.knots_u: decreasing at index 3"},
    {NURBS_PRIM("\"degree\": [1, 1], \"knots_u\": [0, 0, 1, 1], \"knots_v\": [0, 0, 1, 1], \"poles\": [[[0,0,0,1],[1,0,0,1]],[[0,1,1,1]]]", "\"trim_u\": 1"),
     C2B_ERR_SPEC, 0, "primaries[0].nurbs.poles[1]"},
    {NURBS_PRIM("\"degree\": [1, 1], \"knots_u\": [0, 0, 1, 1], \"knots_v\": [0, 0, 1, 1], \"poles\": [[[0,0,0,1],[1,0,0,0]],[[0,1,1,1],[1,1,1,1]]]", "\"trim_u\": 1"),
     C2B_ERR_SPEC, 0, "primaries[0].nurbs.poles[0][1]: weight must be positive"},
    {NURBS_PRIM("\"degree\": [3, 1], \"knots_u\": [0, 0, 0, 0, 1, 1, 1, 1], \"knots_v\": [0, 0, 1, 1], " GOOD_POLES, "\"trim_u\": 1"),
     C2B_ERR_SPEC, 0, "primaries[0].nurbs: degree 3 in u needs at least 4 poles, got 2"},
    {NURBS_PRIM("\"degree\": [1, 1], \"knots_u\": [0, 0, 1, 1], \"knots_v\": [0, 0, 1, 1], " GOOD_POLES, "\"trim_u\": 1.5"),
     C2B_ERR_SPEC, 0, "primaries[0].trim_u: 1.5 is outside the knot range [0, 1]"},
    {NURBS_PRIM("\"degree\": [1, 1], \"knots_u\": [0, 0, 1, 1], \"knots_v\": [0, 0, 1, 1], " GOOD_POLES, "\"trim_u\": 1, \"trim_v\": 0"),
     C2B_ERR_SPEC, 0, "primaries[0]: give exactly one of trim_u and trim_v"},
    {NURBS_PRIM("\"degree\": [1, 1], \"knots_u\": [0, 0, 1, 1], \"knots_v\": [0, 0, 1, 1], \"weights\": [1], " GOOD_POLES, "\"trim_u\": 1"),
     C2B_ERR_SPEC, 0, "primaries[0].nurbs: unknown key 'weights'"},
    {NURBS_PRIM("\"degree\": [1, 1], \"knots_u\": [0, 0, 1], \"knots_v\": [0, 0, 1, 1], " GOOD_POLES, "\"trim_u\": 1"),
     C2B_ERR_SPEC, 0, "primaries[0].nurbs.knots_u: 3 values given, 4 needed"},
    {"{\"force\": [\"exp(u)*cos(v)\", \"0\", \"0\"], \"periodic\": true, " GOOD_PRIM "}",
     0, C2B_ERR_SPEC, "force[0]: the force must be a polynomial in u"},
    {"{\"force\": [\"0\", \"0\"], " GOOD_PRIM "}", C2B_ERR_SPEC, 0, "force: expected 3 expressions"},
    {"{\"time\": 1e999, " GOOD_PRIM "}", C2B_ERR_SPEC, 0, "time: must be finite"},
    {"{\"tolerance\": 2, " GOOD_PRIM "}", C2B_ERR_SPEC, 0, "tolerance: relative truncation tolerance"},
};

int main(void)
{
    for (size_t i = 0; i < sizeof CASES / sizeof *CASES; i++) {
        const bad_case *c = &CASES[i];
        c2b_spec *s = NULL;
        c2b_error err;
        c2b_error_clear(&err);
        c2b_status st = c2b_spec_parse(c->json, strlen(c->json), &s, &err);
        c2b_status want = c->spec_status;
        if (!st && c->blend_status) {
            c2b_blend *b = NULL;
            st = c2b_blend_create(c2b_spec_problem(s), &b, &err);
            want = c->blend_status;
            c2b_blend_destroy(b);
        }
        c2b_spec_destroy(s);
        char what[200];
        snprintf(what, sizeof what, "case %zu: status %d (want %d)", i, (int)st, (int)want);
        check_true(what, st == want);
        snprintf(what, sizeof what, "case %zu: message contains \"%s\"", i, c->fragment);
        if (!check_true(what, strstr(err.msg, c->fragment) != NULL))
            printf("     got: %s\n", err.msg);
    }
    /* The spec's own example from the issue parses and solves. */
    static const char *GOOD =
        "{\"name\": \"x\", \"description\": \"d\", \"source\": \"s\", \"continuity\": \"C2\","
        " \"shape\": [1, 1, 1, 1], \"v_range\": [0, 1], \"periodic\": true,"
        " \"constants\": {\"a\": 1.6, \"b\": 1, \"c\": 0.8, \"d\": 0.6, \"h1\": 2.0, \"h2\": 3, \"h3\": 5},"
        " \"time\": 0.0, \"primaries\": ["
        " {\"surface\": [\"a*exp(t)*sin(2*pi*v)\", \"b*exp(-t)*cos(2*pi*v)\", \"h1+h2*u^2\"], \"trim_u\": 0.2, \"direction\": -1},"
        " {\"surface\": [\"c*exp(-t)*sin(2*pi*v)\", \"d*exp(t)*cos(2*pi*v)\", \"-h3*u^3\"], \"trim_u\": 0.3, \"direction\": 1}],"
        " \"force\": [\"0\", \"0\", \"0\"]}";
    c2b_spec *s = NULL;
    c2b_blend *b = NULL;
    c2b_error err;
    check_true("issue example parses", c2b_spec_parse(GOOD, strlen(GOOD), &s, &err) == C2B_OK);
    check_true("issue example solves", s && c2b_blend_create(c2b_spec_problem(s), &b, &err) == C2B_OK);
    check_true("name is kept", s && !strcmp(c2b_spec_name(s), "x"));
    c2b_blend_destroy(b);
    c2b_spec_destroy(s);
    s = NULL;

    /* Constants: 256 distinct names parse; 257 are over the limit, which is checked
     * before the names are compared pairwise (a repeated one is found as above). */
    for (int count = 256; count <= 257; count++) {
        char json[8192] = "{\"constants\": {";
        size_t used = strlen(json);
        for (int k = 0; k < count; k++)
            used += (size_t)snprintf(json + used, sizeof json - used, "%s\"k%d\": %d",
                                     k ? ", " : "", k, k);
        snprintf(json + used, sizeof json - used, "}, %s}", GOOD_PRIM);
        c2b_status st = c2b_spec_parse(json, strlen(json), &s, &err);
        if (count == 256) {
            check_true("256 constants parse", st == C2B_OK);
        } else {
            check_true("257 constants: over the limit", st == C2B_ERR_LIMIT);
            check_true("257 constants: the message says so",
                       strstr(err.msg, "constants: more than 256") != NULL);
        }
        c2b_spec_destroy(s);
        s = NULL;
    }
    return test_summary("test_spec");
}
