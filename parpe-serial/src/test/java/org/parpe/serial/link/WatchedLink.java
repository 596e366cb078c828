package org.parpe.serial.link;

import java.io.IOException;

/**
 * A link that shows each write to a test before it goes on; the test may swallow it, as a cable
 * to one device being out would (tests only).
 */
public final class WatchedLink implements ByteLink {
    /** Sees one write; false swallows it. */
    public interface Watcher {
        boolean pass(byte[] b, int off, int len);
    }

    private final ByteLink inner;
    private final Watcher watcher;

    public WatchedLink(ByteLink inner, Watcher watcher) {
        this.inner = inner;
        this.watcher = watcher;
    }

    @Override
    public void write(byte[] b, int off, int len) throws IOException {
        if (watcher.pass(b, off, len)) {
            inner.write(b, off, len);
        }
    }

    @Override
    public int read(byte[] b) throws IOException {
        return inner.read(b);
    }

    @Override
    public String name() {
        return inner.name();
    }

    @Override
    public void close() {
        inner.close();
    }
}
