# Turns the compiler's complaints about scripts/check-student-headers' probe into one
# line per book function. Input 1: the functions the probe lines check, in order
# (NAME <tab> OUR DECLARATION <tab> OUR HEADER). Input 2: the compiler's output (GCC's
# wording; another compiler's first error is printed as it is).
FNR == NR {
  function_of[NR] = $1
  ours[NR] = $2
  header_of[NR] = $3
  next
}

# An error on a probe line: which function, and what kind of error.
index($0, probe ":") == 1 && / error: / {
  split(substr($0, length(probe) + 2), where, ":")
  current = where[1] - first + 1
  if (!(current in function_of)) {
    current = 0
    other = other == "" ? $0 : other
    next
  }
  mismatched[current] = $0
  order[++count] = current
  next
}

# A declaration of theirs among the candidates: "FILE:LINE:COLUMN: note: candidates
# are: 'DECLARATION'" or "FILE:LINE:COLUMN: note:                 'DECLARATION'"; the
# probe's own overload is not one.
current && /: note: +(candidate[^:]*: +)?'/ && index($0, probe ":") != 1 && !(current in yours) {
  declaration = $0
  sub(/^[^']*'/, "", declaration)
  sub(/'$/, "", declaration)
  split($0, where, ":")
  yours[current] = declaration
  at[current] = where[1] ":" where[2]
  next
}

/ error: / && other == "" {
  other = $0  # not on a probe line: in their headers themselves
}

END {
  for (i = 1; i <= count; i++) {
    n = order[i]
    if (!(n in yours)) {
      printf "%s: %s is not declared in your headers: the tests need `%s` (%s)\n", chapter,
             function_of[n], ours[n], header_of[n]
    } else {
      printf "%s: %s written with another signature: yours `%s`, the tests need `%s` (%s)\n",
             at[n], function_of[n], yours[n], ours[n], header_of[n]
    }
  }
  if (count == 0 && other != "") {
    printf "%s: your headers do not compile on their own: %s\n", chapter, other
  }
}
