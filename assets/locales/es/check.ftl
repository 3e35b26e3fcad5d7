# check.ftl (es): filled in by the area's translation.
