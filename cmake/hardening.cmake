# The hardening flags Debian's dpkg-buildflags gives a package (lintian checks the .deb for them):
# fortified libc calls (-D_FORTIFY_SOURCE=2, which needs optimisation, so only the optimised build
# types) and a read-only GOT (-z relro with -z now, symbols bound at load time; the viewer module
# is already dlopen'ed with RTLD_NOW). Sanitizer and fuzzer builds keep their own checks: ASan does
# not see through glibc's __*_chk variants, so they get no _FORTIFY_SOURCE.
set(sweep_optimised $<CONFIG:Release,RelWithDebInfo,MinSizeRel>)
if(NOT SWEEP_SANITIZE)
  add_compile_definitions($<${sweep_optimised}:_FORTIFY_SOURCE=2>)
endif()
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  add_link_options($<${sweep_optimised}:LINKER:-z,relro,-z,now>)
endif()
