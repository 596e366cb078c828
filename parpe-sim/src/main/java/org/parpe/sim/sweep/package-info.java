/**
 * Gait sweeps and optimisation on the simulator, for the command line and the IDE alike:
 * {@link org.parpe.sim.sweep.SweepSpec} says what to vary, {@link org.parpe.sim.sweep.Sweep}
 * runs every combination on fresh simulated robots in parallel and streams
 * {@link org.parpe.sim.sweep.SweepRow}s in combination order, and
 * {@link org.parpe.sim.sweep.Optimizer} searches a script's bounded parameters with CMA-ES
 * (Apache Commons Math). Progress reaches a {@link org.parpe.sim.sweep.SweepListener} from the
 * worker threads; a {@link org.parpe.sim.sweep.Cancellation} stops work at the next tick.
 * Nothing here prints to a terminal or touches a widget.
 *
 * <p>A dialog uses it like this, on a thread of its own (never the UI thread):
 * <pre>{@code
 * Evaluator ev = Evaluator.load(new Evaluator.Settings(file, editorText, Map.of(), "snake:n=8", 30, 0.01, 90));
 * List<Axis> axes = List.of(VarySpec.parse("bend=10..70:7", ev.parameters()));   // or Axis.even(...)
 * Sweep sweep = new Sweep(ev, SweepSpec.grid(axes, 1, seed));
 * SweepResult r = sweep.run(jobs, new SweepListener() {
 *     public void progress(int done, int total) { display.asyncExec(() -> bar.setSelection(done)); }
 *     public void row(SweepRow row) { display.asyncExec(() -> table.add(row)); }
 * }, cancellation);                                       // the Stop button calls cancellation.cancel()
 * r.best(Objective.FORWARD_SPEED);                        // rows and best run for a plot
 *
 * OptimizationResult o = new Optimizer(ev, new OptimizeSpec(Objective.FORWARD_SPEED,
 *         new Constraints(60, true), 300, 4, seed)).run(jobs, listener, cancellation);
 * o.bestSoFar();                                          // the convergence curve
 * String newText = ParameterDefaults.rewrite(file, editorText, ev.parameters(), o.best().get().row().values());
 * }</pre>
 * {@link org.parpe.sim.sweep.SweepException} messages are single lines for the user;
 * {@link org.parpe.sim.sweep.SweepSpec#declaredSpace} gives the search space the script declares
 * (to fill the dialog), and {@link org.parpe.sim.sweep.SweepCsv} writes and merges the CSV form.
 */
package org.parpe.sim.sweep;
