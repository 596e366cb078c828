package org.parpe.cli.hw;

import org.parpe.cli.text.CliMsg;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.PrintWriter;
import java.util.concurrent.atomic.AtomicBoolean;
import org.parpe.cli.options.OutputFile;
import org.parpe.cli.options.UsageException;
import org.parpe.serial.record.PoseRecorder;
import org.parpe.serial.record.PoseRecording;
import org.parpe.serial.record.RecordingWriter;

/**
 * One {@code parpe record} session once the group is limp: captures poses on Enter or on a
 * timer, rewrites the file after each pose, and on any ending (end of input, count, or Ctrl-C
 * through {@link #end}) makes the group hold and reports where the recording is.
 */
final class RecordingSession {
    private final PoseRecorder recorder;
    private final PoseRecording recording;
    private final OutputFile out;
    private final String origin;
    private final String playWith;
    private final PrintWriter err;
    private final AtomicBoolean ended = new AtomicBoolean();
    private final long start = System.nanoTime();
    private long last = start;

    /** {@code playWith}: the options that play the recording back on the same robot ({@code --hardware P}). */
    RecordingSession(PoseRecorder recorder, PoseRecording recording, OutputFile out, String origin, String playWith,
                     PrintWriter err) {
        this.recorder = recorder;
        this.recording = recording;
        this.out = out;
        this.origin = origin;
        this.playWith = playWith;
        this.err = err;
    }

    /** Records until the input ends, {@code count} poses were taken, or the JVM is stopped. */
    int run(Integer everyMs, Integer count, BufferedReader in) throws IOException, InterruptedException, UsageException {
        err.println("record: " + (everyMs == null ? CliMsg.RECORD_BY_ENTER.text(recording.group(), ModuleList.format(recording.modules()))
                : CliMsg.RECORD_EVERY.text(recording.group(), ModuleList.format(recording.modules()), everyMs)));
        try {
            while (count == null || recording.size() < count) {
                if (everyMs == null) {
                    if (in.readLine() == null) {
                        break;
                    }
                } else {
                    Thread.sleep(Math.max(0, everyMs - (System.nanoTime() - last) / 1_000_000));
                }
                capture();
            }
        } finally {
            end();
        }
        return recording.size() == 0 ? 1 : 0;
    }

    private synchronized void capture() throws IOException, UsageException {
        if (ended.get()) {
            return;
        }
        double[] pose = new double[recording.modules().length];
        int silent = recorder.capture(pose);
        if (silent >= 0) {
            err.println("record: " + CliMsg.POSE_NOT_CAPTURED.text(silent));
            return;
        }
        long now = System.nanoTime();
        recording.add(pose, (now - last) / 1e9);
        last = now;
        out.write(RecordingWriter.toParsl(recording, origin));
        err.println(RecordCommand.describe(recording.size(), (now - start) / 1e9, pose));
    }

    /**
     * Makes the group hold and reports; runs once, from the main thread or at Ctrl-C (registered
     * to run before the serial port is closed).
     */
    void end() {
        if (!ended.compareAndSet(false, true)) {
            return;
        }
        synchronized (this) {
            try {
                recorder.end();
            } catch (IOException e) {
                err.println("record: " + CliMsg.GROUP_NOT_HOLDING.text(e.getMessage()));
            }
            if (recording.size() == 0) {
                err.println("record: " + CliMsg.NO_POSE_CAPTURED.text(out));
            } else {
                err.println("record: " + CliMsg.POSES_SAVED.text(recording.size(), out, playWith));
            }
            err.flush();
        }
    }
}
