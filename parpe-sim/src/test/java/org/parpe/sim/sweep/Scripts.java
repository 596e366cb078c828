package org.parpe.sim.sweep;

import java.nio.file.Path;
import java.util.Map;

/** A small wave snake with bounded parameters, shared by the sweep tests. */
final class Scripts {
    static final Path FILE = Path.of("sweep-snake.xml");
    static final String SNAKE = """
            <program>
              <robot><structure><body elements="0..5"/></structure></robot>
              <parameters>
                <bend   value="10"  min="0"   max="60"/>
                <period value="4"   min="0.5" max="5"/>
                <phase  value="0.9" min="0"   max="1"/>
              </parameters>
              <main><go/></main>
              <behaviors><go><wave group="body" phase="phase" period="period"/></go></behaviors>
              <automata><wave states="up, down"/></automata>
              <states><up angles="bend" interp="smooth"/><down angles="-bend" interp="smooth"/></states>
            </program>
            """;

    private Scripts() {
    }

    static Evaluator snake(double duration, Map<String, Double> fixed) throws SweepException {
        return Evaluator.load(new Evaluator.Settings(FILE, SNAKE, fixed, "snake:n=6", duration, 0.01, 90));
    }
}
