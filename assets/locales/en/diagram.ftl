# diagram.ftl (en): filled in by the area's translation.
