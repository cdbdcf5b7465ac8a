# Summarises a ctest run of the student build, per chapter and per book function; a
# chapter that does not compile gets one line and the first error.
# Input 1: ctest's Testing/Temporary/LastTest.log (for "not written yet: Name").
# Input 2: ctest's console lines "N/M Test #K: NAME .... Status", sorted by K.
# A test belongs to the function its name starts with ("TraceRay keeps ...",
# "IntersectRaySphere: ..."; not "Listing 6-1 ..."), else to "golden images" or
# "pinned pixels"; any other test is a line of its own, under its name.

# For a failed test, the reason to print under it: the image diagnosis ("your image
# is ours moved one row down") or else its numbers, and its first wrong pixel; else the
# first failed check with what its values were, and what it was given (INFO).
# A name and its verdict, the verdict in the column after 22 characters of names; a
# longer name on a line of its own above it, so that every verdict starts in one column.
function row(name, verdict) {
  if (length(name) > 22) {
    printf "  %s\n  %-22s %s\n", name, "", verdict
  } else {
    printf "  %-22s %s\n", name, verdict
  }
}

function trimmed(text) {
  sub(/^ +/, "", text)
  sub(/ +$/, "", text)
  return text
}

FNR == NR {
  if ($0 ~ /^[0-9]+\/[0-9]+ Test: /) {
    current = $0
    sub(/^[0-9]+\/[0-9]+ Test: /, "", current)
    stage = 0
  } else if (current ~ /: compiles and links$/ && !(current in reason_of) &&
             $0 ~ /(error|undefined reference|out of memory)/) {
    reason_of[current] = trimmed($0)  # the compiler's or linker's first complaint
  } else if (match($0, /not written yet: [A-Za-z_0-9:]+/)) {
    missing_of[current] = substr($0, RSTART + 17, RLENGTH - 17)
  } else if ($0 ~ /^ *first differing pixel: / && !(current in pixel_of)) {
    pixel_of[current] = trimmed($0)  # an image's first wrong pixel: where, yours, ours
  } else if (stage == 6 && $0 ~ /^with messages?:$/) {
    stage = 7
  } else if (stage == 7 && $0 ~ /^  /) {
    # what the check was given (a case's "TraceRay, case 5 of 02-basic-rays.json: what
    # it catches; args ..."), over as many lines as Catch wrapped it to
    given_of[current] = given_of[current] (given_of[current] == "" ? "" : " ") trimmed($0)
  } else if (current in reason_of) {
    stage = 0  # one reason a test is enough
  } else if ($0 ~ /^ *diagnosis: /) {
    reason_of[current] = trimmed($0)
  } else if ($0 ~ /: FAILED:$/) {
    stage = 1
  } else if ((stage == 1 || stage == 2) && $0 ~ /^ *due to unexpected exception with messages?:/) {
    stage = 4
  } else if (stage == 4 && $0 ~ /^  /) {
    # e.g. "written with another signature: ...", over as many lines as Catch wrapped it to
    thrown[current] = thrown[current] (thrown[current] == "" ? "" : " ") trimmed($0)
  } else if (stage == 4) {
    reason_of[current] = "threw: " thrown[current]
    stage = 0
  } else if (stage == 1 && $0 ~ /^ *explicitly with messages?:/) {
    stage = 5
  } else if (stage == 5 && $0 ~ /^  FAIL: /) {
    message_of[current] = trimmed($0)  # an image's numbers, used when no diagnosis follows
  } else if (stage == 5 && $0 ~ /^  / && $0 !~ /^  golden image: / && !(current in message_of)) {
    message_of[current] = trimmed($0)  # a FAIL("...") of a test's own
  } else if (stage == 1 && $0 ~ /^  [A-Z_]+\(/) {
    check_of[current] = trimmed($0)
    stage = 2
  } else if (stage == 2 && $0 ~ /^with expansion:/) {
    stage = 3
  } else if (stage == 3 && $0 ~ /^  /) {
    reason_of[current] = check_of[current] "  is  " trimmed($0)
    stage = 6
  }
  next
}

match($0, /Test +#[0-9]+: /) {
  line = substr($0, RSTART + RLENGTH)
  status = line
  sub(/.* \.+ *(\*\*\*)?/, "", status)
  sub(/ +[0-9.]+ sec$/, "", status)
  name = line
  sub(/ \.+ *(\*\*\*)?[A-Za-z ]+ +[0-9.]+ sec$/, "", name)
  if (name !~ /^[0-9][0-9]-[a-z-]+:/) {
    next  # the build check: the script stops earlier when the build fails
  }
  chapter = name
  sub(/:.*/, "", chapter)
  test_name = substr(name, length(chapter) + 2)
  sub(/^ /, "", test_name)
  if (!(chapter in seen_chapter)) {
    seen_chapter[chapter] = 1
    chapters[++chapter_count] = chapter
  }
  if (test_name == "not written yet") {
    no_folder[chapter] = 1
    next
  }
  if (test_name == "compiles and links") {
    if (status != "Passed") {
      broken[chapter] = (name in reason_of) ? reason_of[name] : "see the build log"
    }
    next
  }
  if (chapter in broken) {
    next  # not run: the chapter did not compile
  }
  if (match(test_name, /^[A-Z][A-Za-z0-9_]*[: ]/) && test_name !~ /^(Listing|Figure) /) {
    group = substr(test_name, 1, RLENGTH - 1)
  } else if (test_name ~ /matches its golden image/) {
    group = "golden images"
  } else if (test_name ~ /^pinned pixels/) {
    group = "pinned pixels"
  } else {
    group = test_name
  }
  key = chapter SUBSEP group
  if (!(key in seen_group)) {
    seen_group[key] = 1
    groups[chapter, ++group_count[chapter]] = group
  }
  if (status == "Passed") {
    passed[key]++
    chapter_passed[chapter]++
  } else if (status == "Skipped") {
    skipped[key]++
    chapter_skipped[chapter]++
    fn = missing_of[name]
    if (fn != "" && !((chapter, fn) in seen_missing)) {
      seen_missing[chapter, fn] = 1
      missing[chapter, ++missing_count[chapter]] = fn
    }
    if (fn != "" && index(" " needs[key] " ", " " fn " ") == 0) {
      needs[key] = needs[key] (needs[key] == "" ? "" : " ") fn
    }
  } else {
    failed[key]++
    chapter_failed[chapter]++
    failures[key] = failures[key] "      " status ": " test_name "\n"
    if ((name in reason_of) && ((chapter, reason_of[name]) in reason_given)) {
      failures[key] = failures[key] "        (the same reason)\n"
    } else if (name in reason_of) {
      reason_given[chapter, reason_of[name]] = 1
      failures[key] = failures[key] "        " reason_of[name] "\n"
      if (name in given_of) {
        failures[key] = failures[key] "        " given_of[name] "\n"
      }
    } else if (name in message_of) {
      failures[key] = failures[key] "        " message_of[name] "\n"
    }
    if (name in pixel_of) {
      failures[key] = failures[key] "        " pixel_of[name] "\n"
    }
  }
}

END {
  for (c = 2; c <= chapter_count; c++) {  # by number, as ctest numbers tests otherwise
    for (d = c; d > 1 && chapters[d - 1] > chapters[d]; d--) {
      swap = chapters[d]; chapters[d] = chapters[d - 1]; chapters[d - 1] = swap
    }
  }
  for (c = 1; c <= chapter_count; c++) {
    chapter = chapters[c]
    if (chapter in no_folder) {
      not_started = not_started (not_started == "" ? "" : ", ") chapter
      continue
    }
    if (chapter in broken) {
      printf "%s: does not compile, so none of its tests ran\n      %s\n", chapter, broken[chapter]
      continue
    }
    printf "%s: %d passed, %d failed, %d not written yet\n", chapter,
           chapter_passed[chapter], chapter_failed[chapter], chapter_skipped[chapter]
    for (g = 1; g <= group_count[chapter]; g++) {
      group = groups[chapter, g]
      key = chapter SUBSEP group
      written = passed[key] + failed[key]
      if (failed[key] > 0) {
        verdict = sprintf("FAILED %d of %d tests", failed[key], written + skipped[key])
      } else if (written > 0) {
        verdict = sprintf("passed (%d test%s)", written, written == 1 ? "" : "s")
      } else {
        verdict = ""
      }
      if (skipped[key] > 0) {
        waiting = (needs[key] == group) ? "not written yet" : "waits for " needs[key]
        if (needs[key] == "") waiting = "not written yet"
        verdict = verdict (verdict == "" ? "" : "; ") \
                  (written > 0 ? skipped[key] " " : "") waiting
      }
      row(group, verdict)
      printf "%s", failures[key]
      is_group[chapter, group] = 1
    }
    for (m = 1; m <= missing_count[chapter]; m++) {
      fn = missing[chapter, m]
      if (!((chapter, fn) in is_group)) {
        row(fn, "not written yet")
      }
    }
  }
  if (not_started != "") {
    printf "not started (no folder yet): %s\n", not_started
  }
}
