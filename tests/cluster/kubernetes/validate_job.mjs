// Validates examples/kubernetes/render-job.yaml offline against the
// Kubernetes API schemas that the npm package kubernetes-models ships
// (compiled from the API's OpenAPI document: types, enums, required
// fields, formats), then checks what the schemas cannot: the Job is an
// Indexed Job whose shard count is its completions, each pod passing
// JOB_COMPLETION_INDEX as Shard_Index, writing into the claimed volume.
//
//     node validate_job.mjs render-job.yaml
//
// A broken copy (a string where the schema wants an integer, an unknown
// completionMode, no containers) must be refused, so a pass means the
// schemas were applied. Not checked (an API server would): unknown field
// names (the published schemas allow extra properties; a server with
// strict field validation rejects them), cross-field rules the API server
// enforces in code (e.g. backoffLimitPerIndex needs completionMode
// Indexed), admission policies and whether the image exists.
import fs from "node:fs";
import yaml from "js-yaml";
import { Job } from "kubernetes-models/batch/v1/Job";
import { PersistentVolumeClaim } from "kubernetes-models/v1/PersistentVolumeClaim";

const models = { Job, PersistentVolumeClaim };

function fail(message) {
    console.log("FAIL: " + message);
    process.exit(1);
}

// Validates every document; returns the list of {kind, doc} or throws.
function validate(text) {
    const docs = yaml.loadAll(text).filter((d) => d !== null);
    for (const doc of docs) {
        const Model = models[doc.kind];
        if (!Model) throw new Error(`no schema for kind ${doc.kind} here`);
        if (doc.apiVersion !== Model.apiVersion)
            throw new Error(`${doc.kind}: apiVersion ${doc.apiVersion}, expected ${Model.apiVersion}`);
        new Model(doc).validate();
    }
    return docs;
}

const path = process.argv[2];
if (!path) fail("usage: node validate_job.mjs FILE.yaml");
const text = fs.readFileSync(path, "utf8");
let docs;
try {
    docs = validate(text);
} catch (e) {
    fail(`${path} does not validate: ${e.message}\n${JSON.stringify(e.errors ?? [], null, 1)}`);
}
for (const d of docs) console.log(`valid ${d.apiVersion} ${d.kind} ${d.metadata.name}`);

const job = docs.find((d) => d.kind === "Job");
const claim = docs.find((d) => d.kind === "PersistentVolumeClaim");
if (!job || !claim) fail("expected a Job and a PersistentVolumeClaim");
const spec = job.spec;
if (spec.completionMode !== "Indexed") fail("the Job is not Indexed: pods get no JOB_COMPLETION_INDEX");
const pod = spec.template.spec;
const container = pod.containers[0];
const command = [...(container.command ?? []), ...(container.args ?? [])].join(" ");
const count = command.match(/Shard_Count=(\d+)/);
if (!count || Number(count[1]) !== spec.completions)
    fail(`Shard_Count (${count && count[1]}) must equal completions (${spec.completions})`);
if (!/Shard_Index=\$\{?JOB_COMPLETION_INDEX\}?/.test(command))
    fail("Shard_Index is not the pod's JOB_COMPLETION_INDEX");
if (!/\+C\b/.test(command)) fail("a retried pod must resume with +C");
if (pod.restartPolicy !== "Never" && pod.restartPolicy !== "OnFailure") fail("restartPolicy");
if (!(claim.spec.accessModes ?? []).includes("ReadWriteMany"))
    fail("every pod writes into one folder: the claim must be ReadWriteMany");
const volume = (pod.volumes ?? []).find((v) => v.persistentVolumeClaim?.claimName === claim.metadata.name);
if (!volume) fail(`no volume of the claim ${claim.metadata.name}`);
const mount = (container.volumeMounts ?? []).find((m) => m.name === volume.name);
const out = command.match(/\+O(\S+)/);
if (!mount || !out || !out[1].startsWith(mount.mountPath.replace(/\/?$/, "/")))
    fail(`the frames (+O${out && out[1]}) are not on the mounted claim`);
console.log(`Indexed Job: ${spec.completions} shards, Shard_Index from JOB_COMPLETION_INDEX, ` +
            `frames under ${mount.mountPath} on ${claim.metadata.name} (ReadWriteMany)`);

// The schemas are applied: broken copies are refused.
const broken = {
    "completions as a string": text.replace(/completions: 8/, 'completions: "eight"'),
    "an unknown completionMode": text.replace(/completionMode: Indexed/, "completionMode: Sharded"),
    "no containers": text.replace(/containers:[\s\S]*?volumes:/, "volumes:"),
    "a volume without a name": text.replace(/- name: frames\n(\s+)persistentVolumeClaim/, "- persistentVolumeClaim"),
};
for (const [what, copy] of Object.entries(broken)) {
    if (copy === text) fail(`could not make the broken copy with ${what}`);
    let refused = false;
    try {
        validate(copy);
    } catch (e) {
        refused = true;
        console.log(`refused, ${what}: ${e.message.split("\n")[0]}`);
    }
    if (!refused) fail(`a copy with ${what} validates: the schemas were not applied`);
}
console.log("PASS");
