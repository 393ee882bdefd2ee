# Fails unless the DLL (-DDLL=...) imports only DLLs of Windows itself, as read by MinGW-w64's
# objdump (-DOBJDUMP=...): a DLL of the compiler's runtime (libstdc++-6.dll, libgcc_s_seh-1.dll,
# libwinpthread-1.dll) or anything else would have to be shipped beside hedge_c.dll, and Unity
# would fail to load the plugin where it is missing. Also fails when the DLL exports a symbol whose
# name does not start with hedge_ (the C ABI is all it offers).
#
cmake_minimum_required(VERSION 3.25)

# Allowed: the kernel and user-mode system DLLs, the C runtimes Windows ships (msvcrt.dll, and the
# Universal CRT's api-ms-win-crt-*.dll forwarders with ucrtbase.dll), and the API set forwarders
# api-ms-win-core-*.dll.
set(allowed_exact kernel32.dll user32.dll advapi32.dll ntdll.dll msvcrt.dll ucrtbase.dll ws2_32.dll
  shell32.dll ole32.dll bcrypt.dll)
set(allowed_prefixes api-ms-win-crt- api-ms-win-core-)

execute_process(COMMAND ${OBJDUMP} -p ${DLL} OUTPUT_VARIABLE dump RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${OBJDUMP} -p ${DLL} failed (${rc})")
endif()
string(REGEX MATCHALL "DLL Name: [^\r\n]+" lines "${dump}")
if(NOT lines)
  message(FATAL_ERROR "${DLL}: objdump lists no imported DLL at all; is it a PE file?")
endif()
set(bad "")
set(seen "")
foreach(line IN LISTS lines)
  string(REGEX REPLACE "^DLL Name: " "" name "${line}")
  string(STRIP "${name}" name)
  string(TOLOWER "${name}" lower)
  list(APPEND seen ${name})
  set(ok FALSE)
  if(lower IN_LIST allowed_exact)
    set(ok TRUE)
  endif()
  foreach(prefix IN LISTS allowed_prefixes)
    string(FIND "${lower}" "${prefix}" at)
    if(at EQUAL 0)
      set(ok TRUE)
    endif()
  endforeach()
  if(NOT ok)
    list(APPEND bad ${name})
  endif()
endforeach()
if(bad)
  message(FATAL_ERROR "${DLL} imports DLLs that are not part of Windows: ${bad}\n"
    "(link them statically: -static, -static-libgcc, -static-libstdc++; all imports: ${seen})")
endif()

# The exports: the [Ordinal/Name Pointer] table's names.
string(REGEX MATCH "\\[Ordinal/Name Pointer\\] Table[^\n]*\n(([ \t]*\\[[^\n]*\n)*)" exports "${dump}")
string(REGEX MATCHALL "\\[ *[0-9]+\\] [^\r\n]+" names "${CMAKE_MATCH_1}")
set(foreign "")
set(exported "")
foreach(entry IN LISTS names)
  string(REGEX REPLACE "^\\[ *[0-9]+\\] " "" name "${entry}")
  list(APPEND exported ${name})
  if(NOT name MATCHES "^hedge_")
    list(APPEND foreign ${name})
  endif()
endforeach()
list(LENGTH exported count)
if(NOT "hedge_mesh_create" IN_LIST exported)
  message(FATAL_ERROR "${DLL} does not export hedge_mesh_create (exports: ${exported})")
endif()
if(foreign)
  message(FATAL_ERROR "${DLL} exports symbols outside the C ABI: ${foreign}")
endif()
message(STATUS "${DLL}: imports ${seen}; ${count} exports, all hedge_*")
