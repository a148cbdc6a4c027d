# The school install, checked end to end (ctest runs this as test_install):
# `cmake --install` into a staging folder and the Debian package from
# `cpack -G DEB` unpacked into another; each time the installed forcelab-cli
# runs an installed lesson, and the installed forcelab answers --help.
#   cmake -DBUILD_DIR=<build> -DSTAGE_DIR=<scratch> -DLESSON_COUNT=<n> -P install_check.cmake

function(must)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(must_out "${out}" PARENT_SCOPE)
endfunction()

# The installed tree under ROOT (with its prefix) has both programs, the
# launcher entry, the icon and every lesson, and they run.
function(check_tree root)
  foreach(f bin/forcelab bin/forcelab-cli share/applications/forcelab.desktop
            share/icons/hicolor/scalable/apps/forcelab.svg share/forcelab/lessons/07-gravity.json)
    if(NOT EXISTS "${root}/${f}")
      message(FATAL_ERROR "not installed: ${root}/${f}")
    endif()
  endforeach()
  file(GLOB lessons "${root}/share/forcelab/lessons/*.json")
  list(LENGTH lessons n)
  if(NOT n EQUAL LESSON_COUNT)
    message(FATAL_ERROR "${n} lessons installed in ${root}, expected ${LESSON_COUNT}")
  endif()
  must("${root}/bin/forcelab-cli" run "${root}/share/forcelab/lessons/07-gravity.json" --steps 60 --json)
  if(NOT must_out MATCHES "\"steps\": *60")
    message(FATAL_ERROR "the installed forcelab-cli did not run 60 steps:\n${must_out}")
  endif()
  must(${CMAKE_COMMAND} -E env QT_QPA_PLATFORM=offscreen "${root}/bin/forcelab" --help)
  if(NOT must_out MATCHES "--present|--screenshot")
    message(FATAL_ERROR "the installed forcelab --help says:\n${must_out}")
  endif()
endfunction()

file(REMOVE_RECURSE "${STAGE_DIR}")

# 1. cmake --install
must(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${STAGE_DIR}/prefix")
check_tree("${STAGE_DIR}/prefix")

# 2. cpack -G DEB, unpacked as dpkg would install it
must(cpack -G DEB -B "${STAGE_DIR}/deb" --config "${BUILD_DIR}/CPackConfig.cmake")
file(GLOB debs "${STAGE_DIR}/deb/*.deb")
list(LENGTH debs n)
if(NOT n EQUAL 1)
  message(FATAL_ERROR "expected one .deb in ${STAGE_DIR}/deb, found: ${debs}")
endif()
must(dpkg-deb --field "${debs}" Package Depends)
if(NOT must_out MATCHES "Package: forcelab" OR NOT must_out MATCHES "libqt6widgets6")
  message(FATAL_ERROR "the package's control fields are wrong:\n${must_out}")
endif()
must(dpkg-deb -x "${debs}" "${STAGE_DIR}/root")
check_tree("${STAGE_DIR}/root/usr")
message(STATUS "installed and ran from ${STAGE_DIR}/prefix and from ${debs}")
