# Summarises a ctest run of the student build, per chapter and per book function.
# Input 1: ctest's Testing/Temporary/LastTest.log (for "not written yet: Name").
# Input 2: ctest's console lines "N/M Test #K: NAME .... Status", sorted by K.
# A test belongs to the function its name starts with ("TraceRay keeps ...",
# "IntersectRaySphere: ..."), else to "golden images", "pinned pixels" or "other tests".

FNR == NR {
  if ($0 ~ /^[0-9]+\/[0-9]+ Test: /) {
    current = $0
    sub(/^[0-9]+\/[0-9]+ Test: /, "", current)
  } else if (match($0, /not written yet: [A-Za-z_0-9]+/)) {
    missing_of[current] = substr($0, RSTART + 17, RLENGTH - 17)
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
  if (match(test_name, /^[A-Z][A-Za-z0-9_]*[: ]/)) {
    group = substr(test_name, 1, RLENGTH - 1)
  } else if (test_name ~ /matches its golden image$/) {
    group = "golden images"
  } else if (test_name ~ /^pinned pixels/) {
    group = "pinned pixels"
  } else {
    group = "other tests"
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
  }
}

END {
  for (c = 1; c <= chapter_count; c++) {
    chapter = chapters[c]
    if (chapter in no_folder) {
      not_started = not_started (not_started == "" ? "" : ", ") chapter
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
      printf "  %-22s %s\n", group, verdict
      printf "%s", failures[key]
      is_group[chapter, group] = 1
    }
    for (m = 1; m <= missing_count[chapter]; m++) {
      fn = missing[chapter, m]
      if (!((chapter, fn) in is_group)) {
        printf "  %-22s not written yet\n", fn
      }
    }
  }
  if (not_started != "") {
    printf "not started (no folder yet): %s\n", not_started
  }
}
