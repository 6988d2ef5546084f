# Enforces the one direction core <- formats <- runtime <- authoring and keeps Qt and OpenEXR out of the
# engine-facing libraries (the player's window in runtime/player may use Qt). Run as: cmake -DSOURCE_DIR=<repo> -P check_dependencies.cmake
# (registered as the ctest "dependencies: one direction, no Qt or OpenEXR in core/formats/runtime").

set(failures "")
function(check_folder folder forbidden_regex why)
  file(GLOB_RECURSE sources "${SOURCE_DIR}/${folder}/*.h" "${SOURCE_DIR}/${folder}/*.cpp")
  foreach(source IN LISTS sources)
    file(STRINGS "${source}" includes REGEX "^[ \t]*#[ \t]*include")
    foreach(line IN LISTS includes)
      if(line MATCHES "${forbidden_regex}")
        file(RELATIVE_PATH relative "${SOURCE_DIR}" "${source}")
        set(failures "${failures}\n  ${relative}: ${line} (${why})" PARENT_SCOPE)
      endif()
    endforeach()
  endforeach()
endfunction()

# Each regex lists what the folder may not include.
check_folder(core "[<\"](Q[A-Za-z]+|Imf[A-Za-z]*|OpenEXR/|kumite/formats/|kumite/runtime/|kumite/authoring/|nlohmann/)"
  "core uses Eigen and the standard library only")
check_folder(formats "[<\"](Q[A-Za-z]+|kumite/runtime/|kumite/authoring/)"
  "formats depends on core only; no Qt")
check_folder(runtime/include "[<\"](Q[A-Za-z]+|Imf[A-Za-z]*|OpenEXR/|openxr/|kumite/authoring/)"
  "libkumite_runtime has no Qt, no OpenEXR and no OpenXR")
check_folder(runtime/src "[<\"](Q[A-Za-z]+|Imf[A-Za-z]*|OpenEXR/|openxr/|kumite/authoring/)"
  "libkumite_runtime has no Qt, no OpenEXR and no OpenXR")
check_folder(core "[<\"]openxr/" "core knows no headset")
check_folder(formats "[<\"]openxr/" "formats knows no headset")
check_folder(runtime/xr "[<\"](Imf[A-Za-z]*|OpenEXR/|kumite/authoring/)"
  "the headset path (Qt, OpenXR) never uses authoring or OpenEXR")
check_folder(runtime/player "[<\"](Imf[A-Za-z]*|OpenEXR/|kumite/authoring/)"
  "the player's window may use Qt, never authoring or OpenEXR")

if(failures)
  message(FATAL_ERROR "dependency rule broken:${failures}")
endif()
message(STATUS "dependencies: core <- formats <- runtime <- authoring respected")
