// etherbone_engine: runs the Etherbone packets of a framed byte link
// (docs/link.md, "Etherbone, the subset" and "UART framing") as a Wishbone
// B4 classic manager, and sends the replies. rtl/link/uart_etherbone.sv puts
// it between a UART with SLIP framing (rtl/link/slip_rx.sv, slip_tx.sv) and
// the bus.
//
// Receive: the frame's bytes (in_data_i) go into a buffer of BUF_BYTES bytes
// (rtl/prim_ram_1r1w.sv: block RAM) with the CRC-32 computed on the fly. At
// the frame's end (in_end_i) the frame runs only if it is whole: no error
// (in_err_i: a framing error or a bad escape), at least 16 bytes (the 8-byte
// header, the 4-byte record header and the CRC), at most BUF_BYTES, and the
// CRC right (the register's residue 0xDEBB20E3 over the frame and its CRC,
// the CRC least significant byte first: rtl/link/crc32.sv). An empty frame
// (END END) is ignored; any other frame is dropped and counted in
// frames_bad_o, and nothing of it runs. While a frame runs or its reply is
// sent (busy_o), the buffer is not written: a frame received then is
// dropped and counted (the host sends one packet and waits for its reply,
// so only a stray or a retransmitted frame meets this).
//
// Run: the packet is the frame without its CRC. Its header must be magic
// 0x4E6F, version 1 (byte 2, bits 7:4) and sizes 0x44 (byte 3), else it is
// dropped and counted (frames_bad_o); bytes 4-7 and the record's flags are
// not looked at. A probe (byte 2 bit 0, pf) is answered with the same
// packet, pf clear and pr (bit 1) set. Otherwise the packet is one record
// and must be exactly as long as its counts say (12 bytes, then 4 + 4 *
// wcount if wcount > 0, then 4 + 4 * rcount if rcount > 0), else it is
// dropped and counted: nothing runs before these checks pass. Then the
// wcount writes to the base write address + 4i (byte addresses; the bus
// address is the byte address / 4), then the rcount reads of the listed byte
// addresses, each with the record's byte enable (bits 3:0) as sel, one at a
// time, cyc and stb high together until ack or err. A bus error (err) on a
// write: the next access goes on; on a read, the word read is 0xFFFFFFFF;
// both count in bus_errors_o. frames_run_o counts the frames that passed
// every check (probes too).
// Reply (to a probe, and to a record with rcount > 0; no reply otherwise):
// END, the packet, its CRC-32 (least significant byte first), END, as
// bytes on out_* (out_end_o marks the two delimiters); a record's reply is
// the header 4E 6F 10 44 00 00 00 00, the record 00, byte enable, rcount,
// 00, the base return address asked, and the words read, each sent as it is
// read. busy_o drops after the last byte is taken.
// The buffer is a simple dual-port RAM used one port at a time (written
// while idle, read while busy), so prim_ram_1r1w needs no bypass logic.
// Formal: rtl/formal/etherbone_engine_props.sv (scripts/formal.sh --blocks
// etherbone_engine). Tests: tests/link/ (through rtl/link/uart_etherbone.sv).
module etherbone_engine #(
  parameter int BUF_BYTES = 1024,  // frame buffer, bytes: a power of two, 16..4096 (a
                                   // frame is at most 2064 bytes: 4096 holds any)
  parameter int CNT_W     = 16     // width of the monitoring counters (1..32; they wrap)
) (
  input  logic             clk_i,
  input  logic             rst_ni,        // asynchronous, active low: idle, counters 0
  // the received frame, decoded (rtl/link/slip_rx.sv): one event a clock
  // at most, but in_err_i may come with in_end_i
  input  logic             in_data_i,     // a data byte of the frame: in_byte_i
  input  logic [7:0]       in_byte_i,
  input  logic             in_end_i,      // the frame ends
  input  logic             in_err_i,      // the frame is bad
  // the reply (rtl/link/slip_tx.sv)
  output logic             out_valid_o,   // a byte to send
  output logic             out_end_o,     // with out_valid_o: a frame delimiter, not data
  output logic [7:0]       out_byte_o,
  input  logic             out_ready_i,   // the byte is taken at this edge
  // Wishbone B4 classic manager; word addresses (byte address / 4)
  output logic             m_cyc_o,
  output logic             m_stb_o,
  output logic             m_we_o,
  output logic [29:0]      m_adr_o,
  output logic [31:0]      m_dat_o,
  output logic [3:0]       m_sel_o,
  input  logic [31:0]      m_dat_i,
  input  logic             m_ack_i,
  input  logic             m_err_i,
  // monitoring (wrapping counters)
  output logic [CNT_W-1:0] frames_run_o,  // frames that passed every check and ran
  output logic [CNT_W-1:0] frames_bad_o,  // frames dropped (CRC, framing, escape, length, format, busy)
  output logic [CNT_W-1:0] bus_errors_o,  // accesses the bus answered with err
  output logic             busy_o         // a frame runs or its reply is being sent
);
`ifndef __ICARUS__
  if (BUF_BYTES < 16 || BUF_BYTES > 4096 || (BUF_BYTES & (BUF_BYTES - 1)) != 0) begin : g_bad_buf
    $error("etherbone_engine: parameter BUF_BYTES must be a power of two, 16..4096");
  end
  if (CNT_W < 1 || CNT_W > 32) begin : g_bad_cnt_w
    $error("etherbone_engine: parameter CNT_W must be 1..32");
  end
`endif

  localparam int AW = $clog2(BUF_BYTES);
  localparam logic [31:0] Residue = 32'hDEBB_20E3;

  typedef enum logic [4:0] {
    Idle,    // receiving
    Hdr,     // fetching bytes 0-3: magic, version and flags, sizes
    Rec,     // fetching bytes 8-11: the record header
    WBase,   // fetching the base write address
    WData,   // fetching a word to write
    WWait,   // writing it
    RHead,   // reply: END, the header and the record header; fetching the base return address
    RBase,   // sending the base return address
    RNext,   // the next read, or the CRC
    RAddr,   // fetching an address to read
    RWait,   // reading it
    Crc,     // reply: the CRC
    TEnd,    // reply: the closing END
    Fin,     // waiting for the last byte to be taken
    Probe,   // probe reply: END
    PByte,   // probe reply: fetching the next byte
    PSend,   // probe reply: sending it
    Drop     // the packet's format is wrong: count it
  } state_e;

  // What the reply bytes come from.
  typedef enum logic [1:0] {
    SrcHdr,    // the 12 header bytes (index from on_q)
    SrcWord,   // w_q, most significant byte first (w_q shifts)
    SrcProbe,  // the probe's byte in w_q[7:0]
    SrcCrc     // the CRC, least significant byte first (index from on_q)
  } src_e;

  state_e           st_q, st_d;
  logic             busy;
  assign busy   = st_q != Idle;
  assign busy_o = busy;

  // --- Receive: buffer, length, error, CRC ---------------------------------
  logic [AW:0]      len_q, len_d;      // bytes of the frame so far (at most BUF_BYTES)
  logic             bad_q, bad_d;      // the frame is already lost
  logic             store, frame_any, frame_ok, rx_bad;
  logic [31:0]      crc;
  // A byte is stored only while idle and while it fits; one that does not
  // (or comes while busy) loses the frame.
  assign store     = in_data_i && !busy && !len_q[AW];
  assign frame_any = len_q != '0 || bad_q || in_err_i;
  assign frame_ok  = in_end_i && !busy && !bad_q && !in_err_i && len_q >= (AW + 1)'(16) &&
                     crc == Residue;
  assign rx_bad    = in_end_i && frame_any && !frame_ok;
  always_comb begin
    len_d = len_q;
    bad_d = bad_q;
    if (in_end_i) begin
      len_d = '0;
      bad_d = 1'b0;
    end else begin
      if (store) len_d = len_q + (AW + 1)'(1);
      if (in_err_i || (in_data_i && !store)) bad_d = 1'b1;
    end
  end

  // --- w_q: the buffer's bytes shift in at the bottom (a fetch of 1..4
  // bytes, two clocks a byte), the reply's bytes shift out at the top; the
  // run never does both at once. A read's answer loads it whole. ---------
  logic [AW-1:0]    rp_q, rp_d;        // the next byte to fetch
  logic [2:0]       fl_q, fl_d;        // bytes left to fetch
  logic             fp_q, fp_d;        // a read was issued: its byte is on rdata now
  logic [31:0]      w_q, w_d;
  logic             re, fetched;
  logic [7:0]       rdata;
  assign re      = fl_q != 3'd0 && !fp_q;
  assign fetched = fl_q == 3'd0 && !fp_q;

  prim_ram_1r1w #(
    .WIDTH       (8),
    .DEPTH       (BUF_BYTES),
    .SAME_WORD_RW(1'b0)  // written only while idle, read only while busy
  ) u_buf (
    .clk_i,
    .we_i   (store),
    .waddr_i(len_q[AW-1:0]),
    .wdata_i(in_byte_i),
    .re_i   (re),
    .raddr_i(rp_q),
    .rdata_o(rdata)
  );

  // --- Reply bytes: on_q of them from src_q, after an END if od_q ----------
  src_e             src_q, src_d;
  logic [3:0]       on_q, on_d;        // bytes left to send
  logic             od_q, od_d;        // an END goes first
  logic             fire, sent;
  logic [7:0]       be_q, be_d;        // the record's byte enable
  logic [7:0]       rc_q, rc_d;        // rcount (the reply header's)
  logic [7:0]       crc_byte;
  assign out_valid_o = od_q || on_q != 4'd0;
  assign out_end_o   = od_q;
  assign fire        = out_valid_o && out_ready_i;
  assign sent        = !out_valid_o;
  always_comb begin
    unique case (on_q[1:0])
      2'd0:    crc_byte = crc[7:0];    // on_q = 4
      2'd3:    crc_byte = crc[15:8];
      2'd2:    crc_byte = crc[23:16];
      default: crc_byte = crc[31:24];
    endcase
    unique case (src_q)
      SrcHdr: begin
        // 4E 6F 10 44 00 00 00 00 | 00 be rcount 00, on_q = 12 down to 1
        unique case (on_q)
          4'd12:   out_byte_o = 8'h4E;
          4'd11:   out_byte_o = 8'h6F;
          4'd10:   out_byte_o = 8'h10;
          4'd9:    out_byte_o = 8'h44;
          4'd3:    out_byte_o = be_q;
          4'd2:    out_byte_o = rc_q;
          default: out_byte_o = 8'h00;
        endcase
      end
      SrcWord:  out_byte_o = w_q[31:24];
      // byte 2 of a probe: pf (bit 0) clear, pr (bit 1) set
      SrcProbe: out_byte_o = rp_q == AW'(3) ? {w_q[7:2], 2'b10} : w_q[7:0];
      default:  out_byte_o = ~crc_byte;
    endcase
  end

  // The CRC: the receiver's while idle, the reply's while busy (every byte
  // but the CRC's own).
  logic             crc_init, crc_en, tx_init;
  logic [7:0]       crc_data;
  assign crc_init = busy ? tx_init : len_q == '0;
  assign crc_en   = busy ? (fire && !od_q && src_q != SrcCrc) : store;
  assign crc_data = busy ? out_byte_o : in_byte_i;
  crc32 u_crc (
    .clk_i,
    .rst_ni,
    .init_i(crc_init),
    .en_i  (crc_en),
    .data_i(crc_data),
    .crc_o (crc)
  );

  // --- The run -------------------------------------------------------------
  logic [AW:0]      plen_q, plen_d;    // the packet's length (the frame less its CRC)
  logic [7:0]       n_q, n_d;          // writes left, then reads left
  logic             cyc_q, cyc_d, we_q, we_d;
  logic [29:0]      adr_q, adr_d;
  logic [CNT_W-1:0] run_q, run_d, badc_q, badc_d, berr_q, berr_d;
  logic             answer, drop, len_ok;
  // the datapath's controls, set by the state machine
  logic             w_load, adr_load, adr_inc, fetch1, fetch4, go, run;
  assign answer = cyc_q && (m_ack_i || m_err_i);
  // The record's length (w_q holds bytes 8-11 when Rec's fetch is done):
  // 12 bytes, then 4 + 4 * wcount if wcount > 0, then 4 + 4 * rcount if
  // rcount > 0; in words, 3 + wcount + rcount + (wcount > 0) + (rcount > 0).
  assign len_ok = plen_q[1:0] == 2'd0 &&
                  11'(plen_q[AW:2]) == 11'd3 + 11'(w_q[15:8]) + 11'(w_q[7:0]) +
                                       11'(w_q[15:8] != 8'd0) + 11'(w_q[7:0] != 8'd0);

  always_comb begin
    st_d     = st_q;
    src_d    = src_q;
    on_d     = on_q;
    od_d     = od_q;
    be_d     = be_q;
    n_d      = n_q;
    rc_d     = rc_q;
    cyc_d    = cyc_q && !answer;
    we_d     = we_q;
    tx_init  = 1'b0;
    drop     = 1'b0;
    run      = 1'b0;
    w_load   = 1'b0;
    adr_load = 1'b0;
    adr_inc  = 1'b0;
    fetch1   = 1'b0;
    fetch4   = 1'b0;
    go       = 1'b0;
    if (fire) begin
      if (od_q) od_d = 1'b0;
      else on_d = on_q - 4'd1;
    end
    unique case (st_q)
      Idle: begin
        if (frame_ok) begin
          go     = 1'b1;
          fetch4 = 1'b1;
          st_d   = Hdr;
        end
      end
      Hdr: begin
        if (fetched) begin
          if (w_q[31:16] != 16'h4E6F || w_q[15:12] != 4'h1 || w_q[7:0] != 8'h44) begin
            st_d = Drop;
          end else if (w_q[8]) begin
            run  = 1'b1;
            st_d = Probe;
          end else begin
            fetch4 = 1'b1;  // bytes 4-7, not looked at
            st_d   = Rec;
          end
        end
      end
      Rec: begin
        // bytes 4-7 fetched on the way in: the second fetch of 4 ends with 8-11
        if (fetched && rp_q == AW'(8)) begin
          fetch4 = 1'b1;
        end else if (fetched) begin
          be_d = w_q[23:16];
          n_d  = w_q[15:8] != 8'd0 ? w_q[15:8] : w_q[7:0];
          rc_d = w_q[7:0];
          if (!len_ok) begin
            st_d = Drop;
          end else begin
            run = 1'b1;
            if (w_q[15:8] != 8'd0) begin
              fetch4 = 1'b1;
              st_d   = WBase;
            end else if (w_q[7:0] != 8'd0) begin
              st_d = RHead;
            end else begin
              st_d = Idle;
            end
          end
        end
      end
      WBase: begin
        if (fetched) begin
          adr_load = 1'b1;
          fetch4   = 1'b1;
          st_d     = WData;
        end
      end
      WData: begin
        if (fetched) begin
          cyc_d = 1'b1;
          we_d  = 1'b1;
          st_d  = WWait;
        end
      end
      WWait: begin
        if (answer) begin
          adr_inc = 1'b1;
          n_d     = n_q - 8'd1;
          if (n_q != 8'd1) begin
            fetch4 = 1'b1;
            st_d   = WData;
          end else if (rc_q != 8'd0) begin
            n_d  = rc_q;
            st_d = RHead;
          end else begin
            st_d = Idle;
          end
        end
      end
      RHead: begin
        tx_init = 1'b1;
        od_d    = 1'b1;
        src_d   = SrcHdr;
        on_d    = 4'd12;
        fetch4  = 1'b1;
        st_d    = RBase;
      end
      RBase: begin
        if (fetched && sent) begin
          src_d = SrcWord;
          on_d  = 4'd4;
          st_d  = RNext;
        end
      end
      RNext: begin
        if (sent) begin
          if (n_q != 8'd0) begin
            fetch4 = 1'b1;
            st_d   = RAddr;
          end else begin
            st_d = Crc;
          end
        end
      end
      RAddr: begin
        if (fetched) begin
          adr_load = 1'b1;
          cyc_d    = 1'b1;
          we_d     = 1'b0;
          st_d     = RWait;
        end
      end
      RWait: begin
        if (answer) begin
          w_load = 1'b1;
          src_d  = SrcWord;
          on_d   = 4'd4;
          n_d    = n_q - 8'd1;
          st_d   = RNext;
        end
      end
      Crc: begin
        if (sent) begin
          src_d = SrcCrc;
          on_d  = 4'd4;
          st_d  = TEnd;
        end
      end
      TEnd: begin
        if (sent) begin
          od_d = 1'b1;
          st_d = Fin;
        end
      end
      Fin: begin
        if (sent) st_d = Idle;
      end
      Probe: begin
        tx_init = 1'b1;
        od_d    = 1'b1;
        st_d    = PByte;
      end
      PByte: begin
        if (sent) begin
          if ({1'b0, rp_q} == plen_q) begin
            st_d = Crc;
          end else begin
            fetch1 = 1'b1;
            st_d   = PSend;
          end
        end
      end
      PSend: begin
        if (fetched) begin
          src_d = SrcProbe;
          on_d  = 4'd1;
          st_d  = PByte;
        end
      end
      default: begin  // Drop: counted when no bad frame is counted in the same clock
        if (!rx_bad) begin
          drop = 1'b1;
          st_d = Idle;
        end
      end
    endcase
  end

  // The datapath.
  always_comb begin
    // the fetch: a read of byte rp_q, its byte shifted in on the next clock
    rp_d = go || (st_q == Hdr && fetched && w_q[8]) ? '0 : re ? rp_q + AW'(1) : rp_q;
    fl_d = fetch4 ? 3'd4 : fetch1 ? 3'd1 : fp_q ? fl_q - 3'd1 : fl_q;
    fp_d = re;
    // w_q: a read's answer (all ones for err), or a byte in (fetch) or out (send)
    if (w_load) w_d = m_dat_i | {32{m_err_i}};
    else if (fp_q || (fire && !od_q && src_q == SrcWord)) w_d = {w_q[23:0], rdata};
    else w_d = w_q;
    adr_d  = adr_load ? w_q[31:2] : adr_inc ? adr_q + 30'd1 : adr_q;
    plen_d = go ? len_q - (AW + 1)'(4) : plen_q;
    run_d  = run ? run_q + CNT_W'(1) : run_q;
    berr_d = answer && m_err_i ? berr_q + CNT_W'(1) : berr_q;
    badc_d = rx_bad || drop ? badc_q + CNT_W'(1) : badc_q;
  end

  assign m_cyc_o      = cyc_q;
  assign m_stb_o      = cyc_q;
  assign m_we_o       = we_q;
  assign m_adr_o      = adr_q;
  assign m_dat_o      = w_q;
  assign m_sel_o      = be_q[3:0];
  assign frames_run_o = run_q;
  assign frames_bad_o = badc_q;
  assign bus_errors_o = berr_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      st_q   <= Idle;
      len_q  <= '0;
      bad_q  <= 1'b0;
      rp_q   <= '0;
      fl_q   <= 3'd0;
      fp_q   <= 1'b0;
      w_q    <= 32'd0;
      src_q  <= SrcHdr;
      on_q   <= 4'd0;
      od_q   <= 1'b0;
      plen_q <= '0;
      be_q   <= 8'd0;
      n_q    <= 8'd0;
      rc_q   <= 8'd0;
      cyc_q  <= 1'b0;
      we_q   <= 1'b0;
      adr_q  <= 30'd0;
      run_q  <= '0;
      badc_q <= '0;
      berr_q <= '0;
    end else begin
      st_q   <= st_d;
      len_q  <= len_d;
      bad_q  <= bad_d;
      rp_q   <= rp_d;
      fl_q   <= fl_d;
      fp_q   <= fp_d;
      w_q    <= w_d;
      src_q  <= src_d;
      on_q   <= on_d;
      od_q   <= od_d;
      plen_q <= plen_d;
      be_q   <= be_d;
      n_q    <= n_d;
      rc_q   <= rc_d;
      cyc_q  <= cyc_d;
      we_q   <= we_d;
      adr_q  <= adr_d;
      run_q  <= run_d;
      badc_q <= badc_d;
      berr_q <= berr_d;
    end
  end
endmodule
