#include "c2b_tolerance.h"

c2b_tolerances c2b_tolerances_default(void)
{
    c2b_tolerances t;
    t.cluster = 1.0;
    t.cond_limit = 1e10;
    t.imag_rel = 1e-8;
    t.truncation_rel = 1e-13;
    t.structure_rel = 1e-12;
    t.drop_rel = 1e-14;
    t.max_poly_degree = 8;
    t.max_samples = 16384;
    t.max_eval_points = 50000000L;
    return t;
}
