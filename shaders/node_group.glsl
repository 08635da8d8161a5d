// A work group per node (ListDispatch with one item per group), for the passes that read a node's
// 3×3×3 neighbourhood: its invocations look the neighbours up together into shared memory, then
// share the node's work. The group's size, NODE_GROUP_SIZE, is picked for the device by
// radiance_filter.cpp; the shader declares it first (octree.glsl's linearInvocation reads
// gl_WorkGroupSize). Requires octree.glsl and brick_gather.glsl.

shared uint sAround[27];  // nodesAround's order

// This invocation's share of filling sAround for `node`; the caller then waits with barrier().
void findNodesAroundTogether(uint node) {
    for (uint o = gl_LocalInvocationIndex; o < 27u; o += gl_WorkGroupSize.x) sAround[o] = nodeAround(node, int(o));
}

// Child v of the 4×4×4 block around the node (gatherChildren's order), from sAround.
uint sharedChildAround(int v) {
    uint slot;
    uint parent = sAround[childAround(v, slot)];
    return parent == NONE ? NONE : childOf(parent, slot);
}
