# diagram.ftl (ru): filled in by the area's translation.
