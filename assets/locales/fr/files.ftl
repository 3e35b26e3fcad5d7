# files.ftl (fr): filled in by the area's translation.
