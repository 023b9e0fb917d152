// A viewer built on Foxglove's published ws-protocol client (npm @foxglove/ws-protocol, over
// the ws package): it connects to argv[2], subscribes to each topic named after it, and prints
// one JSON line with the subprotocol the server chose and, per topic, its channel and the first
// message's payload in base64, for the test to decode. Exit 2 after 30 s without all of them.
const { FoxgloveClient } = require("@foxglove/ws-protocol");
const WebSocket = require("ws");

const [url, ...topics] = process.argv.slice(2);
const ws = new WebSocket(url, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]);
const client = new FoxgloveClient({ ws });
const byTopic = {};
const bySubscription = {};

client.on("error", (error) => {
  console.error(String(error));
  process.exit(1);
});
client.on("advertise", (channels) => {
  for (const channel of channels) {
    if (topics.includes(channel.topic) && !(channel.topic in byTopic)) {
      byTopic[channel.topic] = { channel };
      bySubscription[client.subscribe(channel.id)] = byTopic[channel.topic];
    }
  }
});
client.on("message", ({ subscriptionId, data }) => {
  const entry = bySubscription[subscriptionId];
  if (entry && entry.payload === undefined) {
    entry.payload = Buffer.from(data.buffer, data.byteOffset, data.byteLength).toString("base64");
  }
  if (topics.every((topic) => byTopic[topic] && byTopic[topic].payload !== undefined)) {
    console.log(JSON.stringify({ subprotocol: ws.protocol, topics: byTopic }));
    client.close();
    process.exit(0);
  }
});
setTimeout(() => process.exit(2), 30000);
