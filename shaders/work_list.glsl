// Which node item i of a per-level pass works on: every node of level uLevel, or one entry of the
// level's touched or border list (radiance_common.glsl), chosen at compile time.
uint workNodeAt(uint i, out bool valid) {
#if defined(WORK_LIST_TOUCHED)
    valid = i < listCounts[uLevel];
    return valid ? touchedList[uLevelStart[uLevel] + i] : 0u;
#elif defined(WORK_LIST_BORDER)
    valid = i < listCounts[BORDER_COUNTS + uint(uLevel)];
    return valid ? borderList[uLevelStart[uLevel] + i] : 0u;
#else
    valid = i < uLevelCount[uLevel];
    return uLevelStart[uLevel] + i;
#endif
}
uint workNode(out bool valid) { return workNodeAt(linearInvocation(), valid); }
// For passes whose work groups each take one node (ListDispatch with one item per group).
uint groupWorkNode(out bool valid) { return workNodeAt(linearWorkGroup(), valid); }
