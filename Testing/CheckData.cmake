# Regenerates Data/ into a scratch folder and compares every file with the committed one, so the
# surfaces in Data/ always are what Data/MakeSurfaces.cxx makes.
#   cmake -DGENERATOR=... -DDATA=... -DSCRATCH=... -P CheckData.cmake
file(REMOVE_RECURSE "${SCRATCH}")
file(MAKE_DIRECTORY "${SCRATCH}")
execute_process(COMMAND "${GENERATOR}" "${SCRATCH}" RESULT_VARIABLE rc)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "quadcover_make_surfaces failed (${rc})")
endif ()
file(GLOB made RELATIVE "${SCRATCH}" "${SCRATCH}/*.obj")
list(LENGTH made count)
if (count LESS 5)
  message(FATAL_ERROR "the generator wrote only ${count} surfaces")
endif ()
foreach (name IN LISTS made)
  execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files "${SCRATCH}/${name}" "${DATA}/${name}"
    RESULT_VARIABLE differ)
  if (NOT differ EQUAL 0)
    message(FATAL_ERROR "Data/${name} differs from what the generator makes; run "
      "build/bin/quadcover_make_surfaces Data and commit the result")
  endif ()
endforeach ()
message(STATUS "Data/: ${count} surfaces match the generator")
