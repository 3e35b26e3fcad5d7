# files.ftl (es): filled in by the area's translation.
