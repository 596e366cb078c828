package org.ode4j.ode.internal.processmem;

import org.ode4j.ode.DWorld;
import org.ode4j.ode.internal.DxBody;
import org.ode4j.ode.internal.DxQuickStep;
import org.ode4j.ode.internal.DxWorld;
import org.ode4j.ode.internal.Misc;
import org.ode4j.ode.internal.WarmStart;
import org.ode4j.ode.internal.WorldRandom;
import org.ode4j.ode.internal.joints.DxJoint;
import org.ode4j.ode.internal.joints.DxJointNode;

/**
 * PARPE's own class (not a copy of ODE4j's), in ODE4j's package for its package-private members:
 * {@code DWorld.quickStep} on one thread without allocating. ODE4j's {@code dWorldQuickStep}
 * builds the islands in arrays of an emulated memory arena and steps them through its task
 * framework (task groups, latches, call contexts), all new objects in every step; this does the
 * same steps in the same order with arrays and one call context kept from step to step: auto-
 * disabling, islands found exactly as {@code DxWorldProcessIslandsInfo} finds them (bodies and
 * joints in the same order), then QuickStep on each island in turn, as ODE4j's same-thread
 * executor runs them. Only for a world stepped on one thread (its task executor has one thread);
 * others go through {@code quickStep}. Issue 36; docs/decisions.md, "The simulator's tick
 * allocates nothing".
 */
public final class SequentialQuickStep {
    private final DxWorld world;
    private final DxWorldProcessMemArena arena = new DxWorldProcessMemArena();
    private DxBody[] bodies = new DxBody[0];
    private DxJoint[] joints = new DxJoint[0];
    private DxBody[] stack = new DxBody[0];
    private int[] islandSizes = new int[0];
    private DxStepperProcessingCallContext context;
    private double contextStepSize = Double.NaN;

    private final WarmStart warm;
    private final WorldRandom random = new WorldRandom();
    private long seed;

    /**
     * Steps {@code world}; {@code warm} (or null: from zero, as ODE4j) is what its rows start from,
     * on one thread only (a world stepped on several goes through ODE4j's QuickStep, cold).
     */
    public SequentialQuickStep(DWorld world, WarmStart warm) {
        this.world = (DxWorld) world;
        this.warm = warm;
    }

    /**
     * The seed of the next step's constraint shuffle, as {@code dRandSetSeed} before
     * {@code world.quickStep}: drawn from this world's own generator (ODE4j's global one only for
     * a world stepped on several threads), the same numbers.
     */
    public void seed(long s) {
        seed = s;
    }

    /** One step of {@code stepSize} seconds, as {@code world.quickStep(stepSize)}. */
    public void step(double stepSize) {
        if (world.GetThreadingIslandsMaxThreadsCount(null) != 1) {
            DxQuickStep.onThisThread(null, null);
            Misc.dRandSetSeed(seed);
            world.quickStep(stepSize);
            return;
        }
        if (world.wmem == null) {
            world.wmem = new DxStepWorkingMemory();
        }
        world.wmem.SureGetWorldProcessingContext().EnsureStepperSyncObjectsAreAllocated(world);
        int islands = buildIslands(stepSize);
        if (warm != null) {
            warm.beginStep();
        }
        random.setSeed(seed);
        DxQuickStep.onThisThread(warm, random);
        if (context == null || stepSize != contextStepSize) {
            context = new DxStepperProcessingCallContext(world, stepSize, 1, arena, bodies, joints);
            contextStepSize = stepSize;
        }
        int bodyStart = 0;
        int jointStart = 0;
        for (int i = 0; i < islands; i++) {
            int bcount = islandSizes[2 * i];
            int jcount = islandSizes[2 * i + 1];
            context.AssignIslandSelection(bodies, bodyStart, joints, jointStart, bcount, jcount);
            DxQuickStep.INSTANCE.run(context);
            bodyStart += bcount;
            jointStart += jcount;
        }
        DxQuickStep.onThisThread(null, null);
    }

    /**
     * {@code DxWorldProcessIslandsInfo.BuildIslandsAndEstimateStepperMemoryRequirements}'s search
     * into this object's arrays: the number of islands, whose bodies and joints follow one another
     * in {@link #bodies} and {@link #joints}, their counts in {@link #islandSizes}.
     */
    private int buildIslands(double stepSize) {
        world.dInternalHandleAutoDisabling(stepSize);
        int nb = world.nb;
        int nj = world.nj;
        if (bodies.length < nb) {
            bodies = new DxBody[nb + (nb >> 2) + 16];
            stack = new DxBody[bodies.length];
            islandSizes = new int[2 * bodies.length];
            context = null;
        }
        if (joints.length < nj) {
            joints = new DxJoint[nj + (nj >> 2) + 16];
            context = null;
        }
        for (DxBody b = world.firstbody.get(); b != null; b = (DxBody) b.getNext()) {
            b.tag = 0;
        }
        for (DxJoint j = world.firstjoint.get(); j != null; j = (DxJoint) j.getNext()) {
            j.tag = 0;
        }
        int islands = 0;
        int bodyCurr = 0;
        int jointCurr = 0;
        for (DxBody bb = world.firstbody.get(); bb != null; bb = (DxBody) bb.getNext()) {
            if (bb.tag != 0) {
                continue;
            }
            if (!bb.dBodyIsEnabled()) {
                bb.tag = -1;
                continue;
            }
            bb.tag = 1;
            int bodyStart = bodyCurr;
            int jointStart = jointCurr;
            bodies[bodyCurr++] = bb;
            int stackSize = 0;
            DxBody b = bb;
            while (true) {
                for (DxJointNode n = b.firstjoint.get(); n != null; n = n.next) {
                    DxJoint joint = n.joint;
                    if (joint.tag == 0) {
                        if (joint.isEnabled()) {
                            joint.tag = 1;
                            joints[jointCurr++] = joint;
                            DxBody other = n.body;
                            if (other != null && other.tag <= 0) {
                                other.tag = 1;
                                other.dBodyEnable_noAdis();
                                stack[stackSize++] = other;
                            }
                        } else {
                            joint.tag = -1;
                        }
                    }
                }
                if (stackSize == 0) {
                    break;
                }
                b = stack[--stackSize];
                bodies[bodyCurr++] = b;
            }
            islandSizes[2 * islands] = bodyCurr - bodyStart;
            islandSizes[2 * islands + 1] = jointCurr - jointStart;
            islands++;
        }
        return islands;
    }
}
