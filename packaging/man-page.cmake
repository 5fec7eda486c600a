# cmake -DPROGRAM=... -DNAME=... -DTEMPLATE=... -DOUTPUT=... -P man-page.cmake
# Writes a man page from TEMPLATE with the program's own --help (and that of each subcommand its
# help lists) as its OPTIONS, so the page lists exactly the options the program takes. TEMPLATE's @PROJECT_VERSION@,
# @RESOURCES@ and @DOCS@ are filled in by configure_file (packaging/CMakeLists.txt) beforehand.
cmake_minimum_required(VERSION 3.25)

function(help_text out)
  execute_process(COMMAND "${PROGRAM}" ${ARGN} --help
                  OUTPUT_VARIABLE text ERROR_VARIABLE error RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${PROGRAM} ${ARGN} --help failed (${status}): ${error}")
  endif()
  # the usage line names the program as it was called: the build tree's path
  string(REGEX REPLACE "Usage: [^ \n]*${NAME}" "Usage: ${NAME}" text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# troff: a backslash is \e, a line may not begin with a control character, a minus is \-
function(troff_escaped out text)
  string(REPLACE "\\" "\\e" text "${text}")
  string(REPLACE "-" "\\-" text "${text}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

help_text(text)
# CLI11 lists the subcommands after "Subcommands:", one a line, indented by two spaces
set(subcommands)
if(text MATCHES "\nSubcommands:\n(.*)$")
  string(REGEX MATCHALL "(^|\n)  [a-z][a-z0-9-]*" lines "${CMAKE_MATCH_1}")
  foreach(line IN LISTS lines)
    string(STRIP "${line}" command)
    list(APPEND subcommands ${command})
  endforeach()
endif()
troff_escaped(text "${text}")
set(HELP ".nf\n${text}.fi\n")
foreach(command IN LISTS subcommands)
  help_text(text ${command})
  troff_escaped(text "${text}")
  set(HELP "${HELP}.SS ${NAME} ${command}\n.nf\n${text}.fi\n")
endforeach()

file(READ "${TEMPLATE}" page)
string(REPLACE "@HELP@\n" "${HELP}" page "${page}")
file(WRITE "${OUTPUT}.tmp" "${page}")
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
