# The layers point one way: app → ui → lessons → sim, and inside sim the
# studies use the engine, never the other way. Reads every #include of the
# project's own headers and fails on one that points back up.
#   cmake -DSOURCE=<project source dir> -P check_layers.cmake
#
# Each rule: the folder whose files are read, and the include prefixes they
# must not use. A Qt header (<Q…>) in sim/ is caught by the build already
# (forcelab_sim links no Qt target); ui/drawing/ must not use Qt Widgets,
# which cli_links_no_widgets checks on the program.
set(rules
  "sim/world|sim/studies/,lessons/,ui/,app/"
  "sim/forces|sim/studies/,lessons/,ui/,app/"
  "sim/integrators|sim/studies/,lessons/,ui/,app/"
  "sim/collision|sim/studies/,lessons/,ui/,app/"
  "sim/studies|lessons/,ui/,app/"
  "lessons|ui/,app/"
  "ui/drawing|ui/canvas/,ui/charts/,ui/controls/,ui/docks/,ui/stage/,ui/window/,app/"
  "ui|app/"
)
set(checked 0)
foreach(rule IN LISTS rules)
  string(REPLACE "|" ";" parts "${rule}")
  string(REPLACE "," ";" parts "${parts}")
  list(GET parts 0 folder)
  list(SUBLIST parts 1 -1 forbidden)
  file(GLOB_RECURSE files "${SOURCE}/${folder}/*.h" "${SOURCE}/${folder}/*.cpp")
  if(NOT files)
    message(FATAL_ERROR "no sources under ${folder}: the check reads the wrong place")
  endif()
  foreach(path IN LISTS files)
    file(STRINGS "${path}" includes REGEX "^[ \t]*#[ \t]*include[ \t]+\"")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]+\"([^\"]+)\".*" "\\1" header "${line}")
      foreach(prefix IN LISTS forbidden)
        string(FIND "${header}" "${prefix}" at)
        if(at EQUAL 0)
          file(RELATIVE_PATH shown "${SOURCE}" "${path}")
          message(FATAL_ERROR "${shown} includes ${header}: ${folder}/ must not use ${prefix}")
        endif()
      endforeach()
    endforeach()
    math(EXPR checked "${checked} + 1")
  endforeach()
endforeach()
message(STATUS "layers hold: ${checked} files read")
