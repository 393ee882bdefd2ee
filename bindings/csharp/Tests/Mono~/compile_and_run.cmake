# Compiles C# sources with mcs into an executable and runs it with mono; fails on either error.
#   cmake -DMCS=... -DMONO=... -DFLAGS=-a|-b -DOUT=program.exe -DSOURCES=a.cs|b.cs -P compile_and_run.cmake
# FLAGS and SOURCES are lists joined with "|".
foreach(var MCS MONO OUT SOURCES)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "compile_and_run.cmake: ${var} is not set")
  endif()
endforeach()

string(REPLACE "|" ";" FLAGS "${FLAGS}")
string(REPLACE "|" ";" SOURCES "${SOURCES}")
execute_process(COMMAND ${MCS} ${FLAGS} -out:${OUT} ${SOURCES} RESULT_VARIABLE compiled)
if(NOT compiled EQUAL 0)
  message(FATAL_ERROR "mcs failed (${compiled})")
endif()
message(STATUS "compiled ${OUT}")

execute_process(COMMAND ${MONO} --debug ${OUT} RESULT_VARIABLE ran)
if(NOT ran EQUAL 0)
  message(FATAL_ERROR "${OUT} failed (${ran})")
endif()
