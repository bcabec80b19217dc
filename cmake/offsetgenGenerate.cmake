# offsetgen_generate(): generate offset-function headers and GLSL snippets at build time.
#
#   offsetgen_generate(TARGET <name>
#                      SURFACE <catalog-name>                    # or:
#                      EXPR "<F(x, y[, z])>" NAME <stem> [PARAMS a=0.3 ...]
#                      ORDERS <m> [<m> ...]                      # richardson 1..12, projection 1..16
#                      [METHOD richardson|projection]            # default: offsetgen's default method
#                      [LANG c glsl hlsl wgsl cuda opencl numpy glsl_string]  # default: c; or LANG all
#                      [PRECISION double float]                  # default: double (C only)
#                      [THICKNESS "<t(x, y, z)>"]                # adds <prefix>_graded
#                      [DENSITY <rho>]                           # adds <prefix>_wall and the density functions
#                      [DENSITY_FIELD "<rho(x, y, z)>"]          # adds <prefix>_graded and the density functions
#                      [DENSITY_FUNCTIONS]                       # adds the density functions alone
#                      [MAP "<U; V; W>" | MAP cylindrical:N,A,C  # a conforming lattice (docs/maps.md), with
#                       DOMAIN X0,Y0,Z0:X1,Y1,Z1]                #   the box where it is bounded
#                      [NAME <stem>]                             # with SURFACE: replaces it in the prefix
#                      [OUTPUT_DIR <dir>])                       # default: ${CMAKE_CURRENT_BINARY_DIR}/<name>
#
# THICKNESS, DENSITY and DENSITY_FIELD each set the wall's thickness: give at most one. The density
# functions (<prefix>_density, _thickness_for_density, _network_density, _offset_for_density; see
# docs/density.md) need a periodic 3D surface; offsetgen refuses others when it runs.
#
# For every order m it generates, in OUTPUT_DIR, the files of prefix <stem>_o<m> (stem = NAME, else
# SURFACE; m is the order the method builds: projection rounds odd orders up to the next even one):
# <prefix>.<ext> per language (a backend of src/emit/backends/: .h for c, .glsl, .hlsl, .wgsl, .cuh,
# .cl, .py for numpy), and
# <prefix>_glsl.h (LANG glsl_string: `static const char <prefix>_glsl[]`, the snippet as a C string).
# LANG takes a list (c glsl, or "c,glsl") or all (every backend).
#
# It creates
#   <name>            an INTERFACE library carrying OUTPUT_DIR as include directory; linking it
#                     orders the generation before the consumer's compilation;
#   <name>_generate   the custom target that runs the generator (part of `all`);
# and sets, in the caller's scope and as properties of <name>:
#   <name>_HEADERS / OFFSETGEN_HEADERS                 the C headers (<prefix>.h)
#   <name>_GLSL_FILES / OFFSETGEN_GLSL_FILES           the .glsl snippets
#   <name>_GLSL_STRING_HEADERS / OFFSETGEN_GLSL_STRING_HEADERS   the <prefix>_glsl.h headers
#   <name>_<LANG>_FILES / OFFSETGEN_<LANG>_FILES       the files of each other language (HLSL_FILES, NUMPY_FILES)
#   <name>_OUTPUT_DIR / OFFSETGEN_OUTPUT_DIR           the directory
#
# The generator is offsetgen::offsetgen (find_package(offsetgen) or add_subdirectory), or the host
# executable in the cache variable OFFSETGEN_EXECUTABLE when that is set (cross-compiling).
# Files are regenerated when the generator (its templates are inside it) or the arguments change, and only then;
# offsetgen rewrites a file only when its content changes, so consumers recompile only then.

include_guard(GLOBAL)

set(OFFSETGEN_EXECUTABLE "" CACHE FILEPATH
    "Host offsetgen executable for offsetgen_generate() (cross-compiling); empty: the offsetgen::offsetgen target")

# Reports a configure-time error of offsetgen_generate() and stops.
function(_offsetgen_fail target message)
  if(target)
    message(FATAL_ERROR "offsetgen_generate(TARGET ${target}): ${message}")
  else()
    message(FATAL_ERROR "offsetgen_generate(): ${message}")
  endif()
endfunction()

# The catalog names: what `offsetgen list --json` prints, asked at configure time when the tool
# already exists (an installed or build-tree package, or OFFSETGEN_EXECUTABLE); otherwise (offsetgen
# is built by this project, add_subdirectory) the list read from its source tree.
function(_offsetgen_catalog target tool out)
  get_property(known GLOBAL PROPERTY OFFSETGEN_CATALOG_FROM_TOOL)
  if(NOT known)
    set(tool_path "")
    if(NOT tool STREQUAL "offsetgen::offsetgen")
      set(tool_path "${tool}")
    else()
      get_target_property(imported offsetgen::offsetgen IMPORTED)
      if(imported)
        get_target_property(tool_path offsetgen::offsetgen LOCATION)
      endif()
    endif()
    if(tool_path)
      execute_process(COMMAND "${tool_path}" list --json RESULT_VARIABLE rc OUTPUT_VARIABLE json ERROR_VARIABLE err)
      if(NOT rc EQUAL 0)
        _offsetgen_fail("${target}" "'${tool_path} list --json' failed (${rc}): ${err}")
      endif()
      string(JSON count LENGTH "${json}")
      set(known "")
      math(EXPR last "${count} - 1")
      foreach(i RANGE ${last})
        string(JSON name GET "${json}" ${i} name)
        list(APPEND known "${name}")
      endforeach()
      set_property(GLOBAL PROPERTY OFFSETGEN_CATALOG_FROM_TOOL "${known}")
    else()
      get_property(known GLOBAL PROPERTY OFFSETGEN_SURFACES)
    endif()
  endif()
  set(${out} "${known}" PARENT_SCOPE)
endfunction()

# Writes `content` to `path` only when it differs, so dependants see a new time stamp only then.
function(_offsetgen_write_if_changed path content)
  if(EXISTS "${path}")
    file(READ "${path}" old)
    if(old STREQUAL content)
      return()
    endif()
  endif()
  file(WRITE "${path}" "${content}")
endfunction()

function(offsetgen_generate)
  set(keywords TARGET SURFACE EXPR NAME METHOD THICKNESS DENSITY DENSITY_FIELD DENSITY_FUNCTIONS MAP DOMAIN
               OUTPUT_DIR ORDERS LANG PRECISION PARAMS)
  cmake_parse_arguments(PARSE_ARGV 0 OG "DENSITY_FUNCTIONS"
                        "TARGET;SURFACE;EXPR;NAME;METHOD;THICKNESS;DENSITY;DENSITY_FIELD;MAP;DOMAIN;OUTPUT_DIR"
                        "ORDERS;LANG;PRECISION;PARAMS")
  set(target "")
  if(DEFINED OG_TARGET)
    set(target "${OG_TARGET}")
  endif()
  string(REPLACE ";" ", " keyword_list "${keywords}")

  # --- Arguments -------------------------------------------------------------------------------
  if(DEFINED OG_UNPARSED_ARGUMENTS)
    foreach(value IN LISTS OG_UNPARSED_ARGUMENTS)
      string(TOUPPER "${value}" upper)
      if(upper IN_LIST keywords AND NOT value STREQUAL upper)
        _offsetgen_fail("${target}" "unknown keyword '${value}'; keywords are upper case: ${upper}")
      endif()
    endforeach()
    string(REPLACE ";" " " unparsed "${OG_UNPARSED_ARGUMENTS}")
    _offsetgen_fail("${target}" "unknown keyword or argument(s) '${unparsed}'; the keywords are ${keyword_list}")
  endif()
  if(DEFINED OG_KEYWORDS_MISSING_VALUES)
    _offsetgen_fail("${target}" "keyword(s) ${OG_KEYWORDS_MISSING_VALUES} given without a value")
  endif()
  # After a multi-value keyword a misspelt keyword reads as one more value: name it as what it is.
  # A keyword in the wrong case (orders, Lang) is an unknown keyword too, not a bad value.
  foreach(list_keyword ORDERS LANG PRECISION PARAMS)
    foreach(value IN LISTS OG_${list_keyword})
      string(TOUPPER "${value}" upper)
      if(upper IN_LIST keywords AND NOT value STREQUAL upper)
        _offsetgen_fail("${target}" "unknown keyword '${value}' (read as a value of ${list_keyword}); keywords are upper case: ${upper}")
      endif()
      if(value MATCHES "^[A-Z][A-Z_]+$")
        _offsetgen_fail("${target}" "unknown keyword '${value}' (read as a value of ${list_keyword}); the keywords are ${keyword_list}")
      endif()
    endforeach()
  endforeach()

  if(NOT DEFINED OG_TARGET)
    _offsetgen_fail("" "TARGET <name> is required (the INTERFACE library to create)")
  endif()
  if(NOT target MATCHES "^[A-Za-z0-9_.+-]+$")
    _offsetgen_fail("${target}" "TARGET '${target}' is not a valid target name")
  endif()
  if(TARGET "${target}" OR TARGET "${target}_generate")
    _offsetgen_fail("${target}" "TARGET '${target}' (or '${target}_generate') already exists")
  endif()

  if(DEFINED OG_SURFACE AND DEFINED OG_EXPR)
    _offsetgen_fail("${target}" "give either SURFACE or EXPR, not both")
  elseif(DEFINED OG_SURFACE)
    if(NOT OG_SURFACE MATCHES "^[A-Za-z_][A-Za-z0-9_]*$")
      _offsetgen_fail("${target}" "SURFACE '${OG_SURFACE}' is not a catalog name (see `offsetgen list`)")
    endif()
    set(source_args --surface "${OG_SURFACE}")
    set(stem "${OG_SURFACE}")
  elseif(DEFINED OG_EXPR)
    if(NOT DEFINED OG_NAME)
      _offsetgen_fail("${target}" "EXPR needs NAME <stem>, the stem of the generated names")
    endif()
    set(source_args --expr "${OG_EXPR}")
    set(stem "${OG_NAME}")
  else()
    _offsetgen_fail("${target}" "missing SURFACE <catalog-name> or EXPR \"<expression>\" NAME <stem>")
  endif()
  if(DEFINED OG_NAME)
    if(NOT OG_NAME MATCHES "^[A-Za-z_][A-Za-z0-9_]*$")
      _offsetgen_fail("${target}" "NAME '${OG_NAME}' is not a C identifier (letters, digits, _)")
    endif()
    set(stem "${OG_NAME}")
  endif()

  # The method and its orders, from offsetgen's method registry (see Install.cmake).
  get_property(methods GLOBAL PROPERTY OFFSETGEN_METHODS)
  get_property(method GLOBAL PROPERTY OFFSETGEN_DEFAULT_METHOD)
  if(DEFINED OG_METHOD)
    set(method "${OG_METHOD}")
  endif()
  set(max_order "")
  set(method_names "")
  foreach(entry IN LISTS methods)
    string(REPLACE ":" ";" fields "${entry}")
    list(GET fields 0 name)
    list(APPEND method_names ${name})
    if(name STREQUAL method)
      list(GET fields 1 max_order)
      list(GET fields 2 even_only)
    endif()
  endforeach()
  string(REPLACE ";" ", " method_names "${method_names}")
  if(max_order STREQUAL "")
    _offsetgen_fail("${target}" "METHOD: unknown method '${method}'; expected one of ${method_names}")
  endif()
  set(method_args "")
  if(DEFINED OG_METHOD)
    set(method_args --method "${method}")
  endif()
  if(NOT DEFINED OG_ORDERS)
    _offsetgen_fail("${target}" "ORDERS <m> ... is required (orders 1 to ${max_order} with the ${method} method)")
  endif()
  set(orders "")
  foreach(order IN LISTS OG_ORDERS)
    if(NOT order MATCHES "^[0-9]+$" OR order LESS 1 OR order GREATER max_order)
      _offsetgen_fail("${target}" "ORDERS: order '${order}' is out of range; the ${method} method supports orders 1 to ${max_order}")
    endif()
    math(EXPR order "${order}")  # 04 -> 4, as offsetgen names the files
    list(APPEND orders ${order})
  endforeach()
  list(REMOVE_DUPLICATES orders)

  # The backends ("name:extension" entries, in offsetgen's registry order), plus glsl_string.
  get_property(backends GLOBAL PROPERTY OFFSETGEN_LANGUAGES)
  set(known "")
  foreach(entry IN LISTS backends)
    string(REGEX REPLACE ":.*" "" backend_name "${entry}")
    list(APPEND known ${backend_name})
  endforeach()
  set(want_c OFF)
  set(want_glsl OFF)
  set(want_glsl_string OFF)
  set(languages c)
  if(DEFINED OG_LANG)
    string(REPLACE "," ";" languages "${OG_LANG}")
  endif()
  if(languages STREQUAL "all")
    set(languages ${known})
  endif()
  set(wanted_backends "")
  foreach(language IN LISTS languages)
    if(language STREQUAL "glsl_string")
      set(want_glsl_string ON)
      list(APPEND wanted_backends glsl)
    elseif(language IN_LIST known)
      list(APPEND wanted_backends ${language})
    else()
      string(REPLACE ";" ", " known_text "${known}")
      _offsetgen_fail("${target}" "LANG: unknown language '${language}'; expected ${known_text}, glsl_string or all")
    endif()
  endforeach()
  list(REMOVE_DUPLICATES languages)
  string(REPLACE ";" ", " languages_text "${languages}")
  set(lang_list "")  # registry order, as offsetgen writes them
  set(backend_extensions "")
  foreach(entry IN LISTS backends)
    string(REPLACE ":" ";" parts "${entry}")
    list(GET parts 0 backend_name)
    list(GET parts 1 backend_extension)
    if(backend_name IN_LIST wanted_backends)
      list(APPEND lang_list ${backend_name})
      list(APPEND backend_extensions ${backend_extension})
      set(want_${backend_name} ON)
    endif()
  endforeach()
  string(REPLACE ";" "," lang_arg "${lang_list}")
  if(lang_list STREQUAL known)  # every backend: the banners say --lang all, as a user would type it
    set(lang_arg all)
  endif()

  set(want_double OFF)
  set(want_float OFF)
  set(precisions double)
  if(DEFINED OG_PRECISION)
    set(precisions ${OG_PRECISION})
  endif()
  foreach(precision IN LISTS precisions)
    if(precision STREQUAL "double")
      set(want_double ON)
    elseif(precision STREQUAL "float")
      set(want_float ON)
    else()
      _offsetgen_fail("${target}" "PRECISION: unknown precision '${precision}'; expected double and/or float")
    endif()
  endforeach()
  set(precision_args "")
  if(want_c)  # the GLSL snippet is float-only; --precision concerns the C header
    if(want_double AND want_float)
      set(precision_args --precision both)
    elseif(want_float)
      set(precision_args --precision float)
    else()
      set(precision_args --precision double)
    endif()
  endif()

  set(param_args "")
  foreach(param IN LISTS OG_PARAMS)
    if(NOT param MATCHES "^[A-Za-z_][A-Za-z0-9_]*=.+$")
      _offsetgen_fail("${target}" "PARAMS: '${param}' is not NAME=VALUE")
    endif()
    list(APPEND param_args --param "${param}")
  endforeach()
  set(thickness_args "")
  set(wall_keywords "")
  foreach(keyword THICKNESS DENSITY DENSITY_FIELD)
    if(DEFINED OG_${keyword})
      list(APPEND wall_keywords ${keyword})
    endif()
  endforeach()
  list(LENGTH wall_keywords wall_keyword_count)
  if(wall_keyword_count GREATER 1)
    string(REPLACE ";" " and " wall_keywords "${wall_keywords}")
    _offsetgen_fail("${target}" "give one of THICKNESS, DENSITY and DENSITY_FIELD, not ${wall_keywords}: each sets the wall's thickness")
  endif()
  if(DEFINED OG_MAP)  # offsetgen checks the map and requires its domain
    # "U; V; W" is one argument: its semicolons must not split it into a CMake list.
    string(REPLACE ";" "$<SEMICOLON>" map_arg "${OG_MAP}")
    list(APPEND thickness_args --map "${map_arg}")
  endif()
  if(DEFINED OG_DOMAIN)
    list(APPEND thickness_args --domain "${OG_DOMAIN}")
  endif()
  if(DEFINED OG_THICKNESS)
    list(APPEND thickness_args --thickness "${OG_THICKNESS}")
  endif()
  if(DEFINED OG_DENSITY)
    # The range (0, rho_max] depends on the surface: offsetgen checks it when it runs.
    if(NOT OG_DENSITY MATCHES "^(0?\\.[0-9]+|[0-9]+(\\.[0-9]*)?)([eE][-+]?[0-9]+)?$")
      _offsetgen_fail("${target}" "DENSITY '${OG_DENSITY}' is not a relative density (a number such as 0.2)")
    endif()
    set(thickness_args --density "${OG_DENSITY}")
  endif()
  if(DEFINED OG_DENSITY_FIELD)
    set(thickness_args --density-field "${OG_DENSITY_FIELD}")
  endif()
  if(OG_DENSITY_FUNCTIONS)
    list(APPEND thickness_args --density-functions)
  endif()

  set(output_dir "${CMAKE_CURRENT_BINARY_DIR}/${target}")
  if(DEFINED OG_OUTPUT_DIR)
    get_filename_component(output_dir "${OG_OUTPUT_DIR}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
  endif()

  # --- The generator -----------------------------------------------------------------------------
  if(OFFSETGEN_EXECUTABLE)
    if(NOT EXISTS "${OFFSETGEN_EXECUTABLE}" OR IS_DIRECTORY "${OFFSETGEN_EXECUTABLE}")
      _offsetgen_fail("${target}" "OFFSETGEN_EXECUTABLE '${OFFSETGEN_EXECUTABLE}' does not exist")
    endif()
    set(tool "${OFFSETGEN_EXECUTABLE}")
    set(tool_inputs "${OFFSETGEN_EXECUTABLE}")
  elseif(TARGET offsetgen::offsetgen)
    set(tool offsetgen::offsetgen)
    set(tool_inputs offsetgen::offsetgen)
  else()
    _offsetgen_fail("${target}" "no offsetgen: call find_package(offsetgen) or add_subdirectory(<offsetgen>) first, or set OFFSETGEN_EXECUTABLE to a host offsetgen")
  endif()

  if(DEFINED OG_SURFACE)
    _offsetgen_catalog("${target}" "${tool}" catalog)
    if(catalog AND NOT OG_SURFACE IN_LIST catalog)
      string(REPLACE ";" ", " catalog_text "${catalog}")
      _offsetgen_fail("${target}" "SURFACE '${OG_SURFACE}' is not in offsetgen's catalog; known surfaces: ${catalog_text} (see `offsetgen list`)")
    endif()
  endif()

  # --- One custom command per order --------------------------------------------------------------
  set(glsl_string_script "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/offsetgenGlslString.cmake")
  set(state_dir "${CMAKE_CURRENT_BINARY_DIR}/CMakeFiles/offsetgen_generate/${target}")
  file(MAKE_DIRECTORY "${state_dir}" "${output_dir}")
  set(headers "")
  set(glsl_files "")
  set(glsl_string_headers "")
  foreach(backend_name IN LISTS lang_list)
    set(${backend_name}_files "")
  endforeach()
  set(all_outputs "")
  set(done_prefixes "")
  foreach(order IN LISTS orders)
    set(built_order ${order})
    if(even_only STREQUAL "true")
      math(EXPR built_order "(${order} + 1) / 2 * 2")  # the order the method builds, in the file name
    endif()
    set(prefix "${stem}_o${built_order}")
    if(prefix IN_LIST done_prefixes)  # projection: orders 3 and 4 are the same file
      continue()
    endif()
    list(APPEND done_prefixes ${prefix})
    set(name_args "")
    if(DEFINED OG_NAME OR DEFINED OG_MAP)  # a map's default prefix names the map: keep the stem's
      set(name_args --name "${prefix}")
    endif()
    set(args generate ${source_args} ${param_args} ${name_args} ${method_args} --order ${order} --lang ${lang_arg}
             ${precision_args} ${thickness_args} --out-dir "${output_dir}")

    # The stamp is the primary output, touched on every run, while offsetgen (and the glsl_string
    # script) leave files with unchanged content alone; so after a rerun that changed nothing, e.g.
    # a rebuilt generator, the command does not run again and consumers are not recompiled.
    # Ninja sees the generated files as outputs too (restat). The Makefile generators touch every
    # OUTPUT but the first one after a run, which would recompile consumers for nothing: there
    # they are BYPRODUCTS, which consumers of the INTERFACE library pick up through its target
    # dependency and the compiler's dependency files.
    set(stamp "${state_dir}/${prefix}.stamp")
    # The exact arguments, written only when they change: the Makefile generators do not rerun a
    # custom command whose command line changed, so the command depends on this file.
    set(args_file "${state_dir}/${prefix}.args")
    string(REPLACE ";" "\n" args_text "${tool};${args};glsl_string=${want_glsl_string}")
    _offsetgen_write_if_changed("${args_file}" "${args_text}\n")

    set(outputs "")
    set(commands COMMAND "${tool}" ${args})
    if(want_c)
      list(APPEND outputs "${output_dir}/${prefix}.h")
      list(APPEND headers "${output_dir}/${prefix}.h")
    endif()
    if(want_glsl)
      list(APPEND outputs "${output_dir}/${prefix}.glsl")
      list(APPEND glsl_files "${output_dir}/${prefix}.glsl")
    endif()
    foreach(backend_name backend_extension IN ZIP_LISTS lang_list backend_extensions)
      if(NOT backend_name MATCHES "^(c|glsl)$")
        list(APPEND outputs "${output_dir}/${prefix}.${backend_extension}")
        list(APPEND ${backend_name}_files "${output_dir}/${prefix}.${backend_extension}")
      endif()
    endforeach()
    if(want_glsl_string)
      list(APPEND outputs "${output_dir}/${prefix}_glsl.h")
      list(APPEND glsl_string_headers "${output_dir}/${prefix}_glsl.h")
      list(APPEND commands COMMAND "${CMAKE_COMMAND}" "-DINPUT=${output_dir}/${prefix}.glsl"
           "-DOUTPUT=${output_dir}/${prefix}_glsl.h" "-DNAME=${prefix}_glsl" -P "${glsl_string_script}")
    endif()
    # A generated file gone missing (deleted, or OUTPUT_DIR moved) means the stamp lies: drop it.
    foreach(output IN LISTS outputs)
      if(NOT EXISTS "${output}")
        file(REMOVE "${stamp}")
      endif()
    endforeach()
    list(APPEND all_outputs "${stamp}")
    if(CMAKE_GENERATOR MATCHES "Makefiles")
      set(output_args OUTPUT "${stamp}" BYPRODUCTS ${outputs})
    else()
      set(output_args OUTPUT "${stamp}" ${outputs})
      list(APPEND all_outputs ${outputs})
    endif()
    set(script_inputs "")
    if(want_glsl_string)
      set(script_inputs "${glsl_string_script}")
    endif()
    add_custom_command(
      ${output_args}
      COMMAND "${CMAKE_COMMAND}" -E make_directory "${output_dir}"
      ${commands}
      COMMAND "${CMAKE_COMMAND}" -E touch "${stamp}"
      DEPENDS ${tool_inputs} "${args_file}" ${script_inputs}
      COMMENT "offsetgen: generating ${prefix} (${languages_text}) for ${target}"
      VERBATIM)
  endforeach()

  add_custom_target(${target}_generate ALL DEPENDS ${all_outputs})
  add_library(${target} INTERFACE)
  target_include_directories(${target} INTERFACE "${output_dir}")
  add_dependencies(${target} ${target}_generate)
  set_target_properties(${target} PROPERTIES
    OFFSETGEN_HEADERS "${headers}"
    OFFSETGEN_GLSL_FILES "${glsl_files}"
    OFFSETGEN_GLSL_STRING_HEADERS "${glsl_string_headers}"
    OFFSETGEN_OUTPUT_DIR "${output_dir}")
  foreach(backend_name IN LISTS lang_list)
    if(NOT backend_name MATCHES "^(c|glsl)$")
      string(TOUPPER "${backend_name}" upper)
      set_target_properties(${target} PROPERTIES OFFSETGEN_${upper}_FILES "${${backend_name}_files}")
      set(${target}_${upper}_FILES "${${backend_name}_files}" PARENT_SCOPE)
    endif()
  endforeach()
  set(${target}_HEADERS "${headers}" PARENT_SCOPE)
  set(${target}_GLSL_FILES "${glsl_files}" PARENT_SCOPE)
  set(${target}_GLSL_STRING_HEADERS "${glsl_string_headers}" PARENT_SCOPE)
  set(${target}_OUTPUT_DIR "${output_dir}" PARENT_SCOPE)
endfunction()
