# Compiles one generated HLSL snippet as glslang's HLSL front end sees it (-D), to Vulkan SPIR-V
# (-V), and validates the module with spirv-val. The snippet is pasted twice into a compute shader
# (the include guard must keep the second copy out) that calls every function it declares, so none
# is dead-stripped before validation.
#   cmake -DSNIPPET=<prefix>.hlsl -DWORK_DIR=<dir> -DGLSLANG=<glslangValidator> -DSPIRV_VAL=<spirv-val>
#         -P compile_hlsl.cmake
foreach(var SNIPPET WORK_DIR GLSLANG SPIRV_VAL)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "compile_hlsl.cmake: -D${var}=... is required")
  endif()
endforeach()
file(READ "${SNIPPET}" snippet)
get_filename_component(stem "${SNIPPET}" NAME_WE)

# Every function: "float3 gyroid_o4_normal(float3 p)", "float gyroid_o4_offset(float3 p, float h)".
string(REGEX MATCHALL "\n(float[23]?) ([A-Za-z_][A-Za-z0-9_]*)\\(([^)]*)\\)" declarations "${snippet}")
if(NOT declarations)
  message(FATAL_ERROR "${SNIPPET}: no function found")
endif()
set(sum "")
set(dims 3)
foreach(declaration IN LISTS declarations)
  string(REGEX MATCH "\n(float[23]?) ([A-Za-z_][A-Za-z0-9_]*)\\(([^)]*)\\)" _ "${declaration}")
  set(type "${CMAKE_MATCH_1}")
  set(name "${CMAKE_MATCH_2}")
  set(params "${CMAKE_MATCH_3}")
  if(name MATCHES "_(sin|cos)$")
    continue()  # the snippet's own trig helpers, called by its functions
  endif()
  if(params MATCHES "^float2 ")
    set(dims 2)
  endif()
  set(call "${name}(p")
  if(params MATCHES ", float ")
    string(APPEND call ", q.w")
  endif()
  string(APPEND call ")")
  if(type STREQUAL "float")
    string(APPEND sum " + ${call}")
  else()
    string(APPEND sum " + dot(${call}, p)")
  endif()
endforeach()
if(dims EQUAL 3)
  set(position "float3 p = q.xyz;")
else()
  set(position "float2 p = q.xy;")
endif()

file(MAKE_DIRECTORY "${WORK_DIR}")
set(shader "${WORK_DIR}/${stem}_compute.hlsl")
file(WRITE "${shader}" "${snippet}\n${snippet}
RWStructuredBuffer<float4> io : register(u0);

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    float4 q = io[id.x];
    ${position}
    io[id.x] = float4(0.0${sum}, 0.0, 0.0, 0.0);
}
")
execute_process(COMMAND "${GLSLANG}" -D -V -S comp -e main -o "${WORK_DIR}/${stem}.spv" "${shader}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "glslangValidator -D -V rejects ${SNIPPET} (pasted twice into ${shader}):\n${out}${err}")
endif()
execute_process(COMMAND "${SPIRV_VAL}" "${WORK_DIR}/${stem}.spv" RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "spirv-val rejects the SPIR-V of ${SNIPPET}:\n${out}${err}")
endif()
message(STATUS "${SNIPPET}: glslang HLSL -> SPIR-V, spirv-val accepts it (${stem}.spv)")
