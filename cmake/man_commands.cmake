# Writes OUT, a help2man --include file with a COMMANDS section: the --help of every subcommand
# that `SWEEP --help` lists, so the man page documents each command's options too.
# Usage: cmake -DSWEEP=path/to/sweep -DOUT=file.h2m -P man_commands.cmake
execute_process(COMMAND ${SWEEP} --help OUTPUT_VARIABLE help RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${SWEEP} --help failed (${status})")
endif()
string(REGEX REPLACE ".*\nSubcommands:\n" "" listed "${help}")
string(REGEX MATCHALL "(^|\n)  [a-z][a-z-]*" names "${listed}")
set(text "[COMMANDS]\nEach command's own --help:\n")
foreach(name IN LISTS names)
  string(STRIP "${name}" name)
  execute_process(COMMAND ${SWEEP} ${name} --help OUTPUT_VARIABLE command_help)
  # Roff: a backslash is \e, and a line starting with . or ' must not be read as a request.
  string(REPLACE "\\" "\\e" command_help "${command_help}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" command_help "${command_help}")
  string(APPEND text ".SS \"sweep ${name}\"\n.nf\n${command_help}.fi\n")
endforeach()
file(WRITE ${OUT} "${text}")
