# Writes the long double twin of a generated header's double-precision scalar functions: the same
# straight-line programs evaluated with 11 more bits, the reference the batch and scalar functions
# are both measured against (tests/batch). Functions are renamed ld_<prefix>_*.
#   cmake -DIN=gyroid_o4.h -DOUT=gyroid_o4_ld.h -DPREFIX=gyroid_o4 -P long_double_twin.cmake
file(READ "${IN}" text)
string(FIND "${text}" "#include <stddef.h>" begin)
if(begin LESS 0)
  message(FATAL_ERROR "${IN}: no '#include <stddef.h>'")
endif()
string(SUBSTRING "${text}" ${begin} -1 text)
string(LENGTH "#include <stddef.h>" skip)
string(SUBSTRING "${text}" ${skip} -1 text)
# The scalar functions' inline sin/cos helpers give way to sinl/cosl (the reference is libm's).
string(FIND "${text}" "#ifndef OFFSETGEN_SCALAR_TRIG_DOUBLE_V1" trig_begin)
if(trig_begin GREATER_EQUAL 0)
  set(trig_end_marker "#endif /* OFFSETGEN_SCALAR_TRIG_DOUBLE_V1 */")
  string(FIND "${text}" "${trig_end_marker}" trig_end)
  string(LENGTH "${trig_end_marker}" trig_end_length)
  math(EXPR trig_end "${trig_end} + ${trig_end_length}")
  string(SUBSTRING "${text}" 0 ${trig_begin} before)
  string(SUBSTRING "${text}" ${trig_end} -1 after)
  set(text "${before}${after}")
endif()
string(REGEX REPLACE "offsetgen_(sin|cos)\\(" "\\1(" text "${text}")
# The double scalar functions end where the float ones or the batch section begin.
foreach(marker "static inline float " "#ifndef OFFSETGEN_SCALAR_TRIG_FLOAT" "/* ---- Batch API" "#endif /* OFFSETGEN_")
  string(FIND "${text}" "${marker}" end)
  if(end GREATER_EQUAL 0)
    string(SUBSTRING "${text}" 0 ${end} text)
  endif()
endforeach()
string(REGEX REPLACE "([^A-Za-z0-9_])double([^A-Za-z0-9_])" "\\1long double\\2" text "${text}")
# Twice: a call directly inside another call's parenthesis shares its delimiter.
foreach(pass 1 2)
  string(REGEX REPLACE "([^A-Za-z0-9_])(sin|cos|tan|sqrt|fabs|exp|log|pow|sinh|cosh|tanh|atan|asin|acos)\\("
         "\\1\\2l(" text "${text}")
endforeach()
string(REGEX REPLACE "([^A-Za-z0-9_])${PREFIX}_" "\\1ld_${PREFIX}_" text "${text}")
file(WRITE "${OUT}" "/* Long double twin of ${PREFIX}'s double functions (tests/batch/long_double_twin.cmake). */\n#include <math.h>\n${text}")
