/* Example consumer: the header gyroid_o4.h and gyroid_o4_glsl.h are generated at build time by
 * offsetgen_generate(). Prints whether a few points lie inside the gyroid wall of thickness t = 0.1
 * (shell < 0), in double and float, and the size of the GLSL snippet held as a C string; with an
 * argument, also writes that string to the file it names. */
#include "gyroid_o4.h"
#include "gyroid_o4_glsl.h"

#include <stdio.h>
#include <string.h>

int main(int argc, char** argv) {
  static const double points[][3] = {
      {0.0, 0.0, 0.0},     /* on the surface */
      {0.03, 0.0, 0.0},    /* about 0.017 from it */
      {0.5, 0.5, 0.5},     /* on the surface */
      {0.25, 0.0, 0.0},    /* F = 1 */
      {0.125, 0.125, 0.125} /* F = 1.5, the maximum */
  };
  const double t = 0.1;
  int status = 0;
  for (size_t i = 0; i < sizeof points / sizeof points[0]; ++i) {
    const double x = points[i][0], y = points[i][1], z = points[i][2];
    const double shell = gyroid_o4_shell(x, y, z, t);
    const float shellf = gyroid_o4_shellf((float)x, (float)y, (float)z, (float)t);
    const int inside = shell < 0.0;
    printf("gyroid_o4 t=%.2f (%.3f, %.3f, %.3f): shell = %+.6e -> %s\n", t, x, y, z, shell,
           inside ? "inside the wall" : "outside the wall");
    if ((shellf < 0.0f) != inside) {
      printf("  float disagrees: shellf = %+.6e\n", (double)shellf);
      status = 1;
    }
  }
  const size_t length = strlen(gyroid_o4_glsl);
  printf("gyroid_o4_glsl: %zu bytes%s\n", length, length + 1 == sizeof gyroid_o4_glsl ? "" : " (embedded NUL!)");
  if (argc > 1) {
    FILE* out = fopen(argv[1], "wb");
    if (!out || fwrite(gyroid_o4_glsl, 1, length, out) != length || fclose(out) != 0) {
      fprintf(stderr, "cannot write %s\n", argv[1]);
      return 1;
    }
  }
  return status;
}
