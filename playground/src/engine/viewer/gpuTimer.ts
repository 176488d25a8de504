/**
 * GPU time of a frame from EXT_disjoint_timer_query_webgl2: one query in flight at a time, polled after the frame
 * until its result is available (or the GPU was disjoint, or it is given up).
 */
export class GpuTimer {
  /** GPU time of the last frame measured, ms; null until one is (or without the extension). */
  gpuMs: number | null = null;
  private pending: WebGLQuery | null = null;
  private disposed = false;
  private ext: { TIME_ELAPSED_EXT: number; GPU_DISJOINT_EXT: number } | null;

  /** @param onResult - Called when a frame's time arrives. */
  constructor(
    private readonly gl: WebGL2RenderingContext,
    private readonly onResult: () => void,
  ) {
    this.ext = gl.getExtension('EXT_disjoint_timer_query_webgl2');
    gl.canvas.addEventListener('webglcontextlost', this.onContextChange);
    gl.canvas.addEventListener('webglcontextrestored', this.onContextChange);
  }

  /** Starts timing a frame; null when the extension is missing or a query is still in flight. */
  begin(): WebGLQuery | null {
    if (!this.ext || this.pending) return null;
    const query = this.gl.createQuery();
    if (!query) return null;
    this.gl.beginQuery(this.ext.TIME_ELAPSED_EXT, query);
    return query;
  }

  /** Ends the frame's query (from {@link begin}) and polls for its result. */
  end(query: WebGLQuery | null): void {
    const { gl, ext } = this;
    if (!query || !ext) return;
    gl.endQuery(ext.TIME_ELAPSED_EXT);
    this.pending = query;
    const poll = (tries: number) => {
      if (this.disposed || this.pending !== query) return;
      const available = gl.getQueryParameter(query, gl.QUERY_RESULT_AVAILABLE);
      const disjoint = gl.getParameter(ext.GPU_DISJOINT_EXT);
      if (available && !disjoint) {
        this.gpuMs = gl.getQueryParameter(query, gl.QUERY_RESULT) / 1e6;
      }
      if (available || disjoint || tries > 100) {
        gl.deleteQuery(query);
        this.pending = null;
        if (available) this.onResult();
        return;
      }
      setTimeout(() => poll(tries + 1), 16);
    };
    setTimeout(() => poll(0), 0);
  }

  /**
   * The context was lost or restored: the query in flight is gone, and the extension is asked for again (none
   * while lost; a restored context has none of the lost one's enabled, and would refuse its enums as invalid).
   */
  private readonly onContextChange = () => {
    this.pending = null;
    this.ext = this.gl.getExtension('EXT_disjoint_timer_query_webgl2');
  };

  dispose(): void {
    this.disposed = true;
    this.gl.canvas.removeEventListener('webglcontextlost', this.onContextChange);
    this.gl.canvas.removeEventListener('webglcontextrestored', this.onContextChange);
  }
}
