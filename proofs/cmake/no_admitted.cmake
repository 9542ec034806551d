# Fails if a Coq proof under DIR is unfinished or rests on a new assumption: the words Admitted,
# admit, Axiom, Conjecture or Parameter (as whole words, comments included: a proof file has no
# reason to say them). run_coqc.cmake also rejects any theorem whose `Print Assumptions` lists an
# axiom, which catches assumptions introduced by other means.
#   cmake -DDIR=proofs -P no_admitted.cmake
file(GLOB_RECURSE files ${DIR}/*.v)
set(bad "")
foreach(f IN LISTS files)
  # One list item per line: ';' and brackets (which CMake's list splitting honours) are neutralised
  # first, since Coq is full of them.
  file(READ ${f} text)
  string(REGEX REPLACE "[][;]" " " text "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  set(n 0)
  foreach(line IN LISTS lines)
    math(EXPR n "${n} + 1")
    if(line MATCHES "(^|[^A-Za-z0-9_'])(Admitted|admit|Axiom|Axioms|Conjecture|Parameter|Parameters)([^A-Za-z0-9_']|$)")
      string(APPEND bad "${f}:${n}: ${line}\n")
    endif()
  endforeach()
endforeach()
list(LENGTH files count)
if(bad)
  message(FATAL_ERROR "unfinished proofs or new assumptions:\n${bad}")
endif()
message(STATUS "${count} Coq files, none Admitted, admit, Axiom, Conjecture or Parameter")
