# check.ftl (pt-BR): filled in by the area's translation.
