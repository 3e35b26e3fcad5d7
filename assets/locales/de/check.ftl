# check.ftl (de): filled in by the area's translation.
