/* Compile check of a generated header's batch API, as C99 and as C++17 (tests/batch/CMakeLists.txt).
 * OFFSETGEN_HEADER names the header, OFFSETGEN_PREFIX its prefix; OFFSETGEN_DIMS (3 by default) and
 * OFFSETGEN_HAS_FLOAT say which functions it holds. Every batch function is called, so the loops
 * are compiled (and, with -fopt-info-vec, reported) in this translation unit. */
#include OFFSETGEN_HEADER

#ifndef OFFSETGEN_DIMS
#define OFFSETGEN_DIMS 3
#endif
#define OG_CAT2(a, b) a##b
#define OG_CAT(a, b) OG_CAT2(a, b)
#define OG_FN(suffix) OG_CAT(OFFSETGEN_PREFIX, suffix)

void use_double(size_t n, const double *x, const double *y, const double *z, const double *w, double *out);
void use_double(size_t n, const double *x, const double *y, const double *z, const double *w, double *out)
{
#if OFFSETGEN_DIMS == 3
    OG_FN(_offset_n)(n, x, y, z, w, out);
    OG_FN(_shell_n)(n, x, y, z, w, out + n);
#else
    (void)z;
    OG_FN(_offset_n)(n, x, y, w, out);
    OG_FN(_shell_n)(n, x, y, w, out + n);
#endif
}

#ifdef OFFSETGEN_HAS_FLOAT
void use_float(size_t n, const float *x, const float *y, const float *z, const float *w, float *out);
void use_float(size_t n, const float *x, const float *y, const float *z, const float *w, float *out)
{
#if OFFSETGEN_DIMS == 3
    OG_FN(_offsetf_n)(n, x, y, z, w, out);
    OG_FN(_shellf_n)(n, x, y, z, w, out + n);
#else
    (void)z;
    OG_FN(_offsetf_n)(n, x, y, w, out);
    OG_FN(_shellf_n)(n, x, y, w, out + n);
#endif
}
#endif
