# Prints the free functions a C++ header declares (not defines) at namespace scope,
# one per line: NAME <tab> RETURN TYPE <tab> PARAMETERS, whitespace collapsed and
# default arguments left out. Templates, inline functions and operators are skipped:
# the chapters' headers declare the book's functions one per statement, so a
# statement-level reading is enough (scripts/check-student-headers reads ours).
{
  line = $0
  sub(/\/\/.*/, "", line)
  if (line !~ /^[ \t]*#/) {
    text = text " " line
  }
}

END {
  depth = 0
  statement = ""
  for (i = 1; i <= length(text); i++) {
    c = substr(text, i, 1)
    if (c == "{" || c == "}") {  # a body, a class or a namespace: not a declaration
      depth += (c == "{") ? 1 : -1
      statement = ""
    } else if (depth == 0 && c == ";") {
      print_declaration(statement)
      statement = ""
    } else if (depth == 0) {
      statement = statement c
    }
  }
}

function print_declaration(s,   open, before, name, type, parameters) {
  gsub(/[ \t]+/, " ", s)
  sub(/^ /, "", s)
  sub(/ $/, "", s)
  if (s !~ /\)$/ || s ~ /operator/ ||
      s ~ /^(template|using|typedef|inline|constexpr|static|extern|enum|struct|class|friend)[ <]/) {
    return
  }
  open = index(s, "(")
  before = substr(s, 1, open - 1)
  sub(/ $/, "", before)
  if (!match(before, /[A-Za-z_][A-Za-z_0-9]*$/)) {
    return
  }
  name = substr(before, RSTART)
  type = substr(before, 1, RSTART - 1)
  sub(/ $/, "", type)
  if (type == "" || type ~ /[()=]/) {
    return
  }
  parameters = substr(s, open + 1)
  sub(/\)$/, "", parameters)
  printf "%s\t%s\t%s\n", name, type, without_defaults(parameters)
}

# "double a, int b = 2" -> "double a, int b": what follows a top-level "=" up to the
# next top-level comma is dropped.
function without_defaults(parameters,   out, nesting, skipping, i, c) {
  out = ""
  nesting = 0
  skipping = 0
  for (i = 1; i <= length(parameters); i++) {
    c = substr(parameters, i, 1)
    if (c ~ /[<([{]/) nesting++
    if (c ~ /[>)\]}]/) nesting--
    if (nesting == 0 && c == "=") skipping = 1
    if (nesting == 0 && c == ",") skipping = 0
    if (!skipping) out = out c
  }
  gsub(/ +,/, ",", out)
  sub(/ +$/, "", out)
  return out
}
