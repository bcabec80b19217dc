// Prototype (bench only): the scalar functions with sin/cos evaluated inline by the batch API's
// branch-free polynomials instead of libm calls. bench/poly_trig_variant.cmake rewrites a generated
// header's double scalar offset and shell into polytrig_<prefix>_offset/_shell calling these.
// The quadrant comes from an int conversion rather than rint(), which is a libm call at plain -O2;
// arguments beyond 1e8 go to libm (a select, not an early return: GCC then shares the reduction of
// a sin and a cos of the same argument).
#pragma once

#include <math.h>

static inline double offsetgen_scalar_sin(double a)
{
    const double v = a * 0.63661977236758138;
    const int qi = (int)((fabs(v) <= 1.0e8) ? v + (v >= 0.0 ? 0.5 : -0.5) : 0.0);
    const double q = (double)qi;
    const double r = ((a - q * 1.5707962512969971) - q * 7.5497894158615964e-08) - q * 5.3903028581581190e-15;
    const double z = r * r;
    const double s = r + r * z * (((((1.58962301576546568e-10 * z - 2.50507477628578073e-08) * z + 2.75573136213857245e-06) * z - 1.98412698295895386e-04) * z + 8.33333333332211859e-03) * z - 1.66666666666666307e-01);
    const double c = 1.0 - 0.5 * z + z * z * (((((-1.13585365213876817e-11 * z + 2.08757008419747317e-09) * z - 2.75573141792967388e-07) * z + 2.48015872888517045e-05) * z - 1.38888888888730564e-03) * z + 4.16666666666665929e-02);
    const double u = (qi & 1) ? c : s;
    return (fabs(a) <= 1.0e8) ? ((qi & 2) ? -u : u) : sin(a);
}

static inline double offsetgen_scalar_cos(double a)
{
    const double v = a * 0.63661977236758138;
    const int qi = (int)((fabs(v) <= 1.0e8) ? v + (v >= 0.0 ? 0.5 : -0.5) : 0.0);
    const double q = (double)qi;
    const double r = ((a - q * 1.5707962512969971) - q * 7.5497894158615964e-08) - q * 5.3903028581581190e-15;
    const double z = r * r;
    const double s = r + r * z * (((((1.58962301576546568e-10 * z - 2.50507477628578073e-08) * z + 2.75573136213857245e-06) * z - 1.98412698295895386e-04) * z + 8.33333333332211859e-03) * z - 1.66666666666666307e-01);
    const double c = 1.0 - 0.5 * z + z * z * (((((-1.13585365213876817e-11 * z + 2.08757008419747317e-09) * z - 2.75573141792967388e-07) * z + 2.48015872888517045e-05) * z - 1.38888888888730564e-03) * z + 4.16666666666665929e-02);
    const double u = (qi & 1) ? s : c;
    return (fabs(a) <= 1.0e8) ? (((qi + 1) & 2) ? -u : u) : cos(a);
}
