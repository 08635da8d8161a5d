// Which node an invocation of a per-level pass works on: every node of level uLevel, or one
// entry of the level's touched or border list (radiance_common.glsl), chosen at compile time.
uint workNode(out bool valid) {
    uint i = linearInvocation();
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
