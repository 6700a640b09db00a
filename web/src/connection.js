// The Foxglove WebSocket protocol v1 client (docs/viewer.md): subscribes to every advertised
// channel whose topic the page draws, decodes Message Data frames (JSON payloads), reconnects with
// backoff, and sends the replay's playback commands.

const SUBPROTOCOL = 'foxglove.websocket.v1';
const OP_MESSAGE_DATA = 0x01;
const MIN_BACKOFF_MS = 250;
const MAX_BACKOFF_MS = 5000;

/** ws://host/ of the page's own server, or the ?ws= override. */
export function defaultUrl(location) {
  const override = new URLSearchParams(location.search).get('ws');
  if (override) return override;
  const scheme = location.protocol === 'https:' ? 'wss' : 'ws';
  return `${scheme}://${location.host}/`;
}

export class Connection {
  /**
   * @param {string} url
   * @param {object} options
   *   topics: Set<string> of topics to subscribe to
   *   onMessage(topic, payload, logTimeNs): a decoded JSON message
   *   onStatus(level, text): a server status (0 info, 1 warning, 2 error) or a local event
   *   onConnected(bool): the socket opened (serverInfo received) / closed
   *   onServerInfo(info)
   */
  constructor(url, options) {
    this.url = url;
    this.options = options;
    this.connected = false;
    this.serverInfo = null;
    this.socket = null;
    this.backoffMs = MIN_BACKOFF_MS;
    this.timer = null;
    this.nextSubscriptionId = 1;
    this.subscriptions = new Map();   // subscription id -> channel
    this.channelToSubscription = new Map();  // channel id -> subscription id
    this.decoder = new TextDecoder('utf-8');
    this.malformed = 0;
  }

  start() {
    this.#open();
  }

  /** Sends a JSON text message if the socket is open; returns whether it was sent. */
  send(message) {
    if (!this.socket || this.socket.readyState !== WebSocket.OPEN) return false;
    this.socket.send(JSON.stringify(message));
    return true;
  }

  #open() {
    this.timer = null;
    let socket;
    try {
      socket = new WebSocket(this.url, [SUBPROTOCOL]);
    } catch (error) {
      this.options.onStatus?.(2, `WebSocket ${this.url}: ${error.message}`);
      this.#scheduleReconnect();
      return;
    }
    socket.binaryType = 'arraybuffer';
    this.socket = socket;
    socket.onmessage = (event) => {
      if (typeof event.data === 'string') this.#onText(event.data);
      else this.#onBinary(event.data);
    };
    socket.onclose = () => {
      if (this.socket !== socket) return;
      this.socket = null;
      this.subscriptions.clear();
      this.channelToSubscription.clear();
      if (this.connected) {
        this.connected = false;
        this.options.onConnected?.(false);
      }
      this.#scheduleReconnect();
    };
    socket.onerror = () => {
      // onclose follows and reconnects.
    };
  }

  #scheduleReconnect() {
    if (this.timer) return;
    const delay = this.backoffMs;
    this.backoffMs = Math.min(MAX_BACKOFF_MS, this.backoffMs * 2);
    this.timer = setTimeout(() => this.#open(), delay);
  }

  #onText(text) {
    let message;
    try {
      message = JSON.parse(text);
    } catch {
      this.malformed++;
      return;
    }
    switch (message.op) {
      case 'serverInfo':
        this.backoffMs = MIN_BACKOFF_MS;  // a server that speaks the protocol: retry fast next time
        this.serverInfo = message;
        this.options.onServerInfo?.(message);
        if (!this.connected) {
          this.connected = true;
          this.options.onConnected?.(true);
        }
        break;
      case 'advertise':
        this.#subscribe(message.channels || []);
        break;
      case 'unadvertise':
        for (const channelId of message.channelIds || []) {
          const subscriptionId = this.channelToSubscription.get(channelId);
          if (subscriptionId !== undefined) {
            this.subscriptions.delete(subscriptionId);
            this.channelToSubscription.delete(channelId);
          }
        }
        break;
      case 'status':
        this.options.onStatus?.(message.level ?? 0, message.message ?? '');
        break;
      default:
        break;  // removeStatus, advertiseServices, parameterValues, ...: not used by the page
    }
  }

  #subscribe(channels) {
    const subscriptions = [];
    for (const channel of channels) {
      if (!this.options.topics.has(channel.topic)) continue;
      if (channel.encoding !== 'json') continue;
      if (this.channelToSubscription.has(channel.id)) continue;
      const id = this.nextSubscriptionId++;
      this.subscriptions.set(id, channel);
      this.channelToSubscription.set(channel.id, id);
      subscriptions.push({ id, channelId: channel.id });
    }
    if (subscriptions.length > 0) this.send({ op: 'subscribe', subscriptions });
  }

  #onBinary(buffer) {
    if (buffer.byteLength < 1) return;
    const view = new DataView(buffer);
    if (view.getUint8(0) !== OP_MESSAGE_DATA) return;  // time, service responses, ...: unused
    if (buffer.byteLength < 13) {
      this.malformed++;
      return;
    }
    const subscriptionId = view.getUint32(1, true);
    const channel = this.subscriptions.get(subscriptionId);
    if (!channel) return;  // unsubscribed meanwhile
    const logTimeNs = view.getUint32(5, true) + view.getUint32(9, true) * 4294967296;
    let payload;
    try {
      payload = JSON.parse(this.decoder.decode(new Uint8Array(buffer, 13)));
    } catch {
      this.malformed++;
      return;
    }
    this.options.onMessage(channel.topic, payload, logTimeNs);
  }
}
